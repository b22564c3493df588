#!/usr/bin/env bash
# tests/root_entries.sh — the repository root holds only the entries the
# README's Layout section documents; F12 screenshots, stray logs and scratch
# files belong elsewhere (.gitignore keeps F12's out of commits).  Checks the
# files git tracks, and the untracked ones it does not ignore (those a
# `git add -A` would commit).  Without git (an exported tree): skipped (77).
set -u
cd "$(dirname "$0")/.."
allowed=" .ci .clang-format .gitignore CMakeLists.txt CMakePresets.json LICENSE README.md book_figures common demos docs exercises fuzz reference scripts tests textures "
if ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  echo "SKIPPED: not a git work tree; nothing to check"; exit 77
fi
bad=$( { git ls-files; git ls-files --others --exclude-standard; } | cut -d/ -f1 | sort -u |
       while read -r e; do case "$allowed" in *" $e "*) ;; *) echo "$e" ;; esac; done)
if [ -n "$bad" ]; then
  echo "FAIL: entries at the repository root outside the documented set (README.md, Layout):"
  echo "$bad" | sed 's/^/  /'
  exit 1
fi
echo "root_entries: the root holds only:$allowed"
