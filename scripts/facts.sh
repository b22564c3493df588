#!/usr/bin/env bash
# scripts/facts.sh KIND — the rows of one kind from every demo's facts file
# (demos/*/facts.tsv; docs/facts.md): each row without its kind, as
# "KEY VALUES... [# reason]", for the shell readers (figures_repro.sh,
# export_c_test.sh, wine_test.sh).  A row of a kind no reader knows is a typo
# that would drop a fact unseen: it fails here, whatever kind was asked for.
set -euo pipefail
kind=${1:?usage: facts.sh KIND}
root=$(cd "$(dirname "$0")/.." && pwd)
known=" duration backend_bound hidden_bound export_bound wine_bound claim_bound "
known+="drawn_from_gl too_slow_softpipe rasterizer_specific glsl_specular softpipe_wrong "
case "$known" in *" $kind "*) ;; *) echo "facts.sh: unknown kind '$kind'" >&2; exit 2 ;; esac
status=0
for f in "$root"/demos/*/facts.tsv; do
  while read -r k rest; do
    case "$k" in '' | \#*) continue ;; esac
    case "$known" in
      *" $k "*) [ "$k" = "$kind" ] && echo "$rest" ;;
      *) echo "facts.sh: ${f#"$root"/}: unknown kind '$k'" >&2; status=1 ;;
    esac
  done <"$f"
done
exit "$status"
