// make_figures — renders every registered book figure into one folder and
// writes the gallery README.md beside them.  The demos are independent: with
// more than one, it runs itself once per demo (--only DEMO), --jobs at a time
// (default: two, or one on a single core), each child with one offscreen
// context for all its demo's figures (one scene: what it measured for one
// figure serves the next of the same state).  A child's output is kept and
// printed in the demos' order when it ends, so what is printed and written
// does not depend on which child finished first; a child that fails fails
// the run with its message (each file is written whole or not at all).
//
//   make_figures [--out DIR] [--backend auto|osmesa|egl|hidden] [--scale F] [--only ID] [--list] [--jobs N]
//                [--memory MB]
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include <algorithm>
#include <condition_variable>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "common/app/side_panel.hpp"
#include "common/gl/context.hpp"
#include "common/core/child_process.hpp"
#include "common/core/error.hpp"
#include "common/app/inspect_view.hpp"
#include "common/gl/figure.hpp"
#include "common/gl/render.hpp"
#include "common/core/scene.hpp"
#include "common/core/sidecar.hpp"
#include "common/gl/export_c.hpp"

namespace {
struct Entry {
  ts::FigureSpec spec;
  std::string demo, command;
  ts::Measurements measurements;
  std::string claim;  // the contents' line: spec.claim, its numbers filled in
};

// A number as the measurement tables print it.
std::string fixed3(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f", v);
  return b;
}

// The same without the zeros that say nothing, for prose: 0.800 -> 0.8,
// 24299.000 -> 24299.
std::string shortNumber(double v) {
  std::string s = fixed3(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

// Text for a markdown table cell: '|' would end the cell.
std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

// The figure's one-line claim with each {name} replaced by that
// measurement's value (bold).  A name the figure did not measure is an
// error: the contents would state a number nobody checked.  A figure with
// no claim line shows its demo's claim measurements (Scene::claim).
std::string claimLine(const ts::FigureSpec& spec, const ts::Scene& scene, const ts::Measurements& m) {
  if (spec.claim.empty()) {
    std::string line;
    for (const ts::Measurement* c : ts::claimed(scene, m))
      line += std::string(line.empty() ? "" : "; ") + "`" + c->name + "` **" + shortNumber(c->value) + "**";
    return line;
  }
  std::string line;
  size_t at = 0;
  while (at < spec.claim.size()) {
    size_t open = spec.claim.find_first_of("{}", at);
    if (open == std::string::npos) {
      line += spec.claim.substr(at);
      break;
    }
    size_t close = spec.claim.find('}', open);
    if (spec.claim[open] == '}' || close == std::string::npos)
      throw ts::Error(spec.id + ": unbalanced braces in its claim \"" + spec.claim + "\"");
    std::string name = spec.claim.substr(open + 1, close - open - 1);
    auto it = std::find_if(m.begin(), m.end(), [&](const ts::Measurement& x) { return x.name == name; });
    if (it == m.end()) throw ts::Error(spec.id + "'s claim names '" + name + "', which it does not measure");
    line += spec.claim.substr(at, open - at) + "**" + shortNumber(it->value) + "**";
    at = close + 1;
  }
  return line;
}

// Where a figure goes in the gallery: the chapter's order, read from its
// book number.  "Figure VI.n" (the book's figures) come first, then "Section
// VI.n.m" and "Buss VI.n" (the figures of the sections), then "Seed n" (the
// lecture seeds'); within each, by the numbers, part by part (VI.10 after
// VI.9).  A book number that names none of these (an exercise) goes after
// the figure before it in its demo: Exercise VI.2 asks about Figure VI.6's torus.
struct Place {
  int part = 3;  // 0 figures, 1 sections, 2 seeds, 3 unknown (last)
  std::vector<int> numbers;
  bool operator<(const Place& o) const { return part != o.part ? part < o.part : numbers < o.numbers; }
};

// "VI" -> 6, "003" -> 3; -1 for anything else.
int numberOrRoman(const std::string& s) {
  if (s.empty() || s.size() > 6) return -1;
  if (std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    return std::stoi(s);
  const std::string roman = "IVXLC";
  const int values[] = {1, 5, 10, 50, 100};
  int total = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    size_t k = roman.find(s[i]);
    if (k == std::string::npos) return -1;
    size_t next = i + 1 < s.size() ? roman.find(s[i + 1]) : std::string::npos;
    total += next != std::string::npos && values[next] > values[k] ? -values[k] : values[k];
  }
  return total;
}

bool placeOf(const std::string& bookNumber, Place& place) {
  size_t space = bookNumber.find(' ');
  std::string kind = bookNumber.substr(0, space);
  for (char& c : kind) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (kind == "figure") place.part = 0;
  else if (kind == "section" || kind == "buss") place.part = 1;
  else if (kind == "seed") place.part = 2;
  else return false;
  // The reference after the word: "VI.1.3", "003:".
  size_t from = space == std::string::npos ? bookNumber.size() : space + 1;
  size_t to = bookNumber.find_first_of(" :(,", from);
  std::string ref = bookNumber.substr(from, to == std::string::npos ? std::string::npos : to - from);
  place.numbers.clear();
  for (size_t at = 0; at <= ref.size();) {
    size_t dot = std::min(ref.find('.', at), ref.size());
    int n = numberOrRoman(ref.substr(at, dot - at));
    if (n < 0) return false;
    place.numbers.push_back(n);
    at = dot + 1;
  }
  return true;
}

std::vector<const Entry*> chapterOrder(const std::vector<Entry>& entries) {
  std::vector<std::pair<Place, const Entry*>> placed;
  for (size_t i = 0; i < entries.size(); ++i) {
    Place p;
    if (!placeOf(entries[i].spec.bookNumber, p))
      for (size_t j = i; j-- > 0;)
        if (entries[j].demo == entries[i].demo) {
          p = placed[j].first;
          break;
        }
    placed.push_back({p, &entries[i]});
  }
  std::stable_sort(placed.begin(), placed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<const Entry*> out;
  for (const auto& p : placed) out.push_back(p.second);
  return out;
}

// GitHub's anchor for a heading: lower case; punctuation but '-' and '_'
// dropped; each space a '-' (two spaces give two).  Other bytes (UTF-8
// letters) are kept as they are.
std::string anchor(const std::string& heading) {
  std::string out;
  for (char c : heading) {
    unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u)) out += char(std::tolower(u));
    else if (c == ' ' || c == '-') out += '-';
    else if (c == '_' || u >= 0x80) out += c;
  }
  return out;
}

std::string heading(const Entry& e) { return e.spec.bookNumber + ": `" + e.spec.id + "`"; }

std::string gallery(const std::vector<Entry>& entries, const std::string& regenerate) {
  std::string md =
      "# Book figures\n\n"
      "Every image here is made by the suite; none is drawn by hand. Regenerate all of them with\n\n"
      "    " +
      regenerate +
      "\n\n"
      "Each PNG has a sidecar `.json` beside it with every parameter needed to recompute it without OpenGL:\n"
      "size, projection and modelview matrices, textures (how they were made, filters, wrap modes), and every\n"
      "vertex with its (s,t,r,q). The measured numbers below are the figure's claim, checked by the tests.\n\n";
  std::vector<const Entry*> order = chapterOrder(entries);
  md += "## Contents\n\n"
        "In the chapter's order: Buss's Figures VI.1-VI.7, then the figures of his sections, then those of the "
        "lecture seeds.\n\n"
        "| figure | claim, measured |\n|---|---|\n";
  for (const Entry* e : order)
    md += "| [" + cell(e->spec.bookNumber) + " `" + e->spec.id + "`](#" + anchor(heading(*e)) + ") | " +
          cell(e->claim) + " |\n";
  md += "\n";
  for (const Entry* p : order) {
    const Entry& e = *p;
    md += "## " + heading(e) + "\n\n";
    md += "![" + e.spec.bookNumber + "](" + e.spec.id + ".png)\n\n";
    md += e.spec.caption + "\n\n";
    md += "Source: [`demos/" + e.demo + "/" + e.demo + ".cpp`](../demos/" + e.demo + "/" + e.demo + ".cpp). ";
    md += "The OpenGL calls that draw it: [`" + e.spec.id + ".gl.txt`](" + e.spec.id + ".gl.txt). ";
    md += "Make just this one:\n\n    " + e.command + "\n\n";
    md += "| measured | value | meaning |\n|---|---|---|\n";
    for (const auto& m : e.measurements)
      md += "| `" + m.name + "` | " + fixed3(m.value) + " | " + cell(m.meaning) + " |\n";
    md += "\n";
  }
  return md;
}

// --only takes figure ids or demo names, comma-separated: "vi1_quad_variants"
// or "quad_distortion,torus" (every figure of those demos).
bool selected(const std::string& only, const std::string& figure, const std::string& demo) {
  size_t start = 0;
  while (start <= only.size()) {
    size_t end = only.find(',', start);
    if (end == std::string::npos) end = only.size();
    std::string item = only.substr(start, end - start);
    if (item == figure || item == demo) return true;
    start = end + 1;
  }
  return false;
}

// A child (--report FILE) writes each measurement of its figures as a line
// of FILE, which the parent reads back for the gallery: a control character
// first, then figure, name, value (exact: %.17g) and meaning, tab-separated
// (none of them holds a tab or a line break).  A file of its own, not the
// child's output, where a line could be cut by what it writes on stderr.
constexpr char kReportMark = '\x1e';

std::string reportLine(const std::string& figure, const ts::Measurement& m) {
  char v[40];
  std::snprintf(v, sizeof v, "%.17g", m.value);
  std::string line = std::string(1, kReportMark) + figure + "\t" + m.name + "\t" + v + "\t" + m.meaning;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  return line + "\n";
}

// A child's output: what it printed and each figure's measurements.
struct ChildOutput {
  std::string text;
  std::map<std::string, ts::Measurements> measured;
};
void parseReport(const std::string& report, ChildOutput& c) {
  size_t at = 0;
  while (at < report.size()) {
    size_t end = report.find('\n', at);
    if (end == std::string::npos) throw ts::Error("a child's report ends inside a line");
    std::string line = report.substr(at, end - at);
    at = end + 1;
    if (line.empty() || line[0] != kReportMark) throw ts::Error("a child's report holds a stray line: " + line);
    std::vector<std::string> f;
    for (size_t from = 1;;) {
      size_t tab = line.find('\t', from);
      f.push_back(line.substr(from, tab == std::string::npos ? std::string::npos : tab - from));
      if (tab == std::string::npos || f.size() == 4) break;
      from = tab + 1;
    }
    if (f.size() != 4) throw ts::Error("a child's report line is cut: " + line.substr(1));
    c.measured[f[0]].push_back({f[1], std::strtod(f[2].c_str(), nullptr), f[3]});
  }
}

// What a demo's figures cost, measured once on a 2-core machine with
// llvmpipe (`/usr/bin/time -v make_figures --only DEMO --jobs 1`: user + sys
// seconds, peak resident MB).  Only the order and the pairing use them: the
// longest start first, so the run does not end on one long demo alone, and
// two children run side by side only while their peaks add up to at most
// the --memory budget.  A demo not listed (a new one) counts as short and
// small; a wrong figure here costs time or memory, never a different output.
struct Cost {
  double seconds;
  int peakMb;
};
Cost costOf(const std::string& demo) {
  static const std::map<std::string, Cost> measured = {
#include "common/app/make_figures_costs.inc"
  };
  auto it = measured.find(demo);
  return it == measured.end() ? Cost{1.0, 250} : it->second;
}

// Each demo in a child of its own (this program with --only DEMO --report),
// `jobs` at a time: the longest first (costOf), a child started only when
// its peak with those of the children running stays within `memoryMb` (or
// when none runs: a demo over the budget runs alone).  Returns each demo's
// output in the demos' order, whichever ended first; throws (with the
// child's message) if one failed: the children still running finish, none
// is started after.
std::vector<ChildOutput> runChildren(const std::vector<std::string>& demos, const std::vector<std::string>& common,
                                     int jobs, int memoryMb) {
  const std::string reports = ts::makeTempFolder("make_figures-");
  if (reports.empty()) throw ts::Error("cannot make a temporary folder for the children's reports");
  struct Remove {  // the reports' folder goes whatever happens
    std::string path;
    ~Remove() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  } removeReports{reports};
  auto reportOf = [&](size_t i) { return reports + "/" + demos[i] + ".txt"; };
  struct Job {
    ts::ProcessResult result;
    bool ran = false;
  };
  std::vector<Job> done(demos.size());
  // The longest first; equal costs in the demos' order.
  std::vector<size_t> order(demos.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return costOf(demos[a]).seconds > costOf(demos[b]).seconds; });
  std::mutex lock;
  std::condition_variable ended;
  std::vector<bool> started(demos.size(), false);
  int running = 0, runningMb = 0;
  bool failed = false;
  const std::string self = ts::programPath("make_figures");
  auto worker = [&] {
    std::unique_lock<std::mutex> hold(lock);
    for (;;) {
      // The first demo not started, in cost order, that fits beside those running.
      size_t pick = demos.size();
      bool left = false;
      for (size_t i : order) {
        if (started[i]) continue;
        left = true;
        if (running == 0 || runningMb + costOf(demos[i]).peakMb <= memoryMb) {
          pick = i;
          break;
        }
      }
      if (failed || !left) break;
      if (pick == demos.size()) {  // none fits: wait for a child to end
        ended.wait(hold);
        continue;
      }
      started[pick] = true;
      const int mb = costOf(demos[pick]).peakMb;
      ++running, runningMb += mb;
      hold.unlock();
      std::vector<std::string> argv = {self, "--only", demos[pick], "--report", reportOf(pick)};
      argv.insert(argv.end(), common.begin(), common.end());
      // No time limit that matters: a figure takes what it takes (a day stops a hung child).
      ts::ProcessResult result = ts::runProcess(argv, "", 86400.0);
      hold.lock();
      done[pick].result = std::move(result);
      done[pick].ran = true;
      const ts::ProcessResult& r = done[pick].result;
      if (!r.started || r.timedOut || r.exitCode != 0) failed = true;
      --running, runningMb -= mb;
      ended.notify_all();
    }
  };
  std::vector<std::thread> threads;
  for (int k = 1; k < std::min<int>(jobs, int(demos.size())); ++k) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  std::vector<ChildOutput> out;
  for (size_t i = 0; i < demos.size(); ++i) {
    const ts::ProcessResult& r = done[i].result;
    if (!done[i].ran) continue;
    if (!r.started || r.timedOut || r.exitCode != 0) {
      std::string text = r.out;
      if (!text.empty() && text.back() != '\n') text += '\n';
      std::fputs(text.c_str(), stderr);
      throw ts::Error(demos[i] + "'s figures failed (" +
                      (!r.started   ? std::string("the program could not be run")
                       : r.timedOut ? std::string("no answer in a day")
                                    : "exit code " + std::to_string(r.exitCode)) +
                      "): nothing more is rendered and the gallery is not written");
    }
    ChildOutput c;
    c.text = r.out;
    std::ifstream in(reportOf(i), std::ios::binary);
    if (!in) throw ts::Error(demos[i] + "'s child wrote no report");
    parseReport(std::string(std::istreambuf_iterator<char>(in), {}), c);
    out.push_back(std::move(c));
  }
  return out;
}

int run(int argc, char** argv) {
  std::string out = "book_figures", backend = "auto", only, scaleText, report;
  // The children's peaks side by side at most this (MB): see costOf.
  int memoryMb = 1000;
  double scale = 1.0;
  bool list = false, exportPrograms = false;
  // Two children at a time: the figures are CPU-bound (llvmpipe, the CPU
  // references), and each child's peak memory adds up.
  int jobs = std::thread::hardware_concurrency() > 1 ? 2 : 1;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto need = [&]() -> std::string {
      if (i + 1 >= argc) throw ts::Error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--out") out = need();
    else if (a == "--backend") backend = need();
    else if (a == "--only") only = need();
    else if (a == "--list") list = true;
    else if (a == "--export-c") exportPrograms = true;
    else if (a == "--report") report = need();  // a child's: its measurements, for the parent
    else if (a == "--jobs") {
      std::string v = need();
      char* end = nullptr;
      long n = std::strtol(v.c_str(), &end, 10);
      if (v.empty() || *end || n < 1 || n > 64) throw ts::Error("--jobs: '" + v + "' is not a number from 1 to 64");
      jobs = int(n);
    } else if (a == "--memory") {
      std::string v = need();
      char* end = nullptr;
      long n = std::strtol(v.c_str(), &end, 10);
      if (v.empty() || *end || n < 1 || n > 1000000)
        throw ts::Error("--memory: '" + v + "' is not a number of megabytes from 1 to 1000000");
      memoryMb = int(n);
    } else if (a == "--scale") {
      std::string v = need();
      scaleText = v;
      char* end = nullptr;
      scale = std::strtod(v.c_str(), &end);
      if (v.empty() || *end || !(scale > 0) || scale > 16) throw ts::Error("--scale: '" + v + "' is not in (0, 16]");
    } else if (a == "--help" || a == "-h") {
      std::printf("usage: make_figures [--out DIR] [--backend auto|osmesa|egl|hidden] "
                  "[--scale F] [--only ID] [--list] [--export-c] [--jobs N] [--memory MB]\n"
                  "Renders every registered book figure (PNG + sidecar JSON + GL listing) and the gallery README.md\n"
                  "into DIR (default book_figures). --scale multiplies every figure's size. --only ID[,ID...]: just\n"
                  "these figures or every figure of these demos (no gallery). --export-c: also each figure as a\n"
                  "standalone C program, DIR/<id>.c and DIR/<id>.texels (see --export-c of the demos). --jobs N:\n"
                  "N demos at a time, each in a process of its own (default 2; 1: all in this process), the longest\n"
                  "first. --memory MB: children side by side only while their measured peaks add up to at most MB\n"
                  "(default 1000; a demo over it runs alone).\n");
      return 0;
    } else throw ts::Error("unknown argument '" + a + "' (see --help)");
  }
  ts::Backend b = ts::parseBackend(backend);
  if (b == ts::Backend::Window) throw ts::Error("figures render offscreen: --backend osmesa, egl, hidden or auto");

  std::vector<Entry> todo;
  for (const auto& reg : ts::sceneRegistry())
    for (const auto& spec : reg.make()->figures()) {
      if (!only.empty() && !selected(only, spec.id, reg.id)) continue;
      Entry e{spec, reg.id, "", {}, ""};
      e.spec.width = std::max(1, int(std::lround(spec.width * scale)));
      e.spec.height = std::max(1, int(std::lround(spec.height * scale)));
      if (e.spec.width > ts::kMaxImageDimension || e.spec.height > ts::kMaxImageDimension)
        throw ts::Error("--scale " + std::to_string(scale) + " makes " + spec.id + " larger than 16384 pixels");
      todo.push_back(e);
    }
  if (list) {
    for (const auto& e : todo)
      std::printf("%-28s %-24s %dx%d  demos/%s\n", e.spec.id.c_str(), e.spec.bookNumber.c_str(), e.spec.width,
                  e.spec.height, e.demo.c_str());
    return 0;
  }
  if (todo.empty()) throw ts::Error("no figure or demo named '" + only + "' (see --list)");
  // std::filesystem: Windows' mkdir() takes no mode.
  std::error_code made;
  if (!std::filesystem::exists(out, made) && !std::filesystem::create_directory(out, made))
    throw ts::Error("cannot create " + out + ": " + made.message());
  ts::checkWritable(out + "/README.md");

  std::vector<std::string> demoOrder;
  for (const Entry& e : todo)
    if (demoOrder.empty() || demoOrder.back() != e.demo) demoOrder.push_back(e.demo);
  if (jobs > 1 && demoOrder.size() > 1 && report.empty()) {
    std::vector<std::string> common = {"--out", out, "--backend", backend};
    if (!scaleText.empty()) common.insert(common.end(), {"--scale", scaleText});
    if (exportPrograms) common.push_back("--export-c");
    std::printf("rendering %zu figures of %zu demos into %s/, %d processes at a time\n", todo.size(), demoOrder.size(),
                out.c_str(), jobs);
    std::fflush(stdout);
    std::map<std::string, ts::Measurements> measured;
    for (ChildOutput& c : runChildren(demoOrder, common, jobs, memoryMb)) {
      std::fputs(c.text.c_str(), stdout);
      for (auto& [id, m] : c.measured) measured[id] = std::move(m);
    }
    std::map<std::string, std::unique_ptr<ts::Scene>> scenes;  // claimLine asks a scene which numbers it claims
    for (Entry& e : todo) {
      auto it = measured.find(e.spec.id);
      if (it == measured.end()) throw ts::Error(e.spec.id + ": its child printed no measurements");
      std::unique_ptr<ts::Scene>& scene = scenes[e.demo];
      if (!scene) scene = ts::makeScene(e.demo);
      std::vector<std::string> flags = {"--json", out + "/" + e.spec.id + ".json"};
      flags.insert(flags.end(), e.spec.flags.begin(), e.spec.flags.end());
      e.command = ts::figureCommand(e.demo, out + "/" + e.spec.id + ".png", e.spec.width, e.spec.height, flags);
      e.measurements = it->second;
      e.claim = claimLine(e.spec, *scene, e.measurements);
    }
    if (only.empty()) {
      std::string regen = "scripts/figures.sh" + std::string(scale != 1.0 ? " --scale " + std::to_string(scale) : "");
      ts::writeFileAtomic(out + "/README.md", gallery(todo, regen));
    }
    return 0;
  }

  ts::ContextOptions co;
  co.verbose = true;
  for (const auto& reg : ts::sceneRegistry()) co.accumBuffer |= reg.make()->wantsAccumBuffer();
  auto ctx = ts::createOffscreenContext(b, co);
  ts::Renderer r(*ctx);
  if (report.empty())  // a child's parent has said it
    std::printf("rendering %zu figures into %s/ with %s\n", todo.size(), out.c_str(), ctx->describe().c_str());
  // One scene per demo for all its figures, each from the defaults and its
  // own flags: what a scene keeps between measurements (the parallax table,
  // the jitter images) serves every figure of the same state.
  struct Demo {
    std::unique_ptr<ts::Scene> scene;
    ts::Options opts;
  };
  std::map<std::string, Demo> demos;
  std::string reportText;  // --report FILE: what goes into it
  for (Entry& e : todo) {
    Demo& d = demos[e.demo];
    if (!d.scene) {
      d.scene = ts::makeScene(e.demo);
      d.scene->addOptions(d.opts);
      d.opts.captureDefaults();
    }
    ts::Scene* scene = d.scene.get();
    ts::Options& opts = d.opts;
    opts.resetToDefaults();
    // A figure's flags are the demo's options and, for the inspection
    // figures, the common --inspect X,Y and --footprints.
    ts::CommonFlags common;
    opts.parse(ts::sceneFlags(e.spec.flags, &common));
    ts::checkPixels(common.inspect, e.spec.width, e.spec.height);
    ts::Rendered got = ts::renderScene(*scene, r, e.spec.width, e.spec.height, true);
    const std::vector<std::string> inspected = ts::applyInspect(e.demo, common, r, &got, true, nullptr);
    std::string png = out + "/" + e.spec.id + ".png", json = out + "/" + e.spec.id + ".json";
    std::string listing = out + "/" + e.spec.id + ".gl.txt";
    std::vector<std::string> flags = {"--json", json};
    flags.insert(flags.end(), e.spec.flags.begin(), e.spec.flags.end());
    e.command = ts::figureCommand(e.demo, png, e.spec.width, e.spec.height, flags);
    // The numbers only: a scene's detail (its pictures, their GL calls) is not kept past its figure.
    e.measurements.assign(got.measurements.begin(), got.measurements.end());
    e.claim = claimLine(e.spec, *scene, got.measurements);
    ts::SidecarInfo info{e.spec.id,        e.spec.bookNumber,
                         e.spec.caption,   e.demo,
                         e.command,        opts.state(),
                         got.measurements, ts::gl::rendererString() + " | " + ts::gl::versionString()};
    info.inspect = inspected;
    ts::writePng(png, got.image);
    ts::writeFileAtomic(json, ts::sidecarJson(got.frame, info));
    ts::writeFileAtomic(listing,
                        ts::glListingFile(got, ts::stateCommand(e.demo, e.spec.width, e.spec.height, e.spec.flags)));
    if (exportPrograms) {
      ts::ExportInfo info;
      info.demo = e.demo;
      info.title = e.spec.bookNumber + ": " + scene->title();
      info.about = scene->about();
      info.state = ts::stateCommand(e.demo, e.spec.width, e.spec.height, e.spec.flags);
      info.width = e.spec.width;
      info.height = e.spec.height;
      std::string c = out + "/" + e.spec.id + ".c";
      ts::nameExport(c, &info);
      ts::writeExport(c, ts::exportC(got.calls, got.frame, info));
    }
    for (const auto& [suffix, text] : scene->figureFiles()) ts::writeFileAtomic(out + "/" + e.spec.id + suffix, text);
    std::printf("%s  %s\n%s", png.c_str(), e.spec.bookNumber.c_str(), ts::formatMeasurements(got.measurements).c_str());
    for (const ts::Measurement& m : got.measurements) reportText += reportLine(e.spec.id, m);
    std::fflush(stdout);  // a child's lines reach its parent in the order printed, stderr's among them
  }
  if (!report.empty()) ts::writeFileAtomic(report, reportText);
  if (only.empty()) {
    std::string regen = "scripts/figures.sh" + std::string(scale != 1.0 ? " --scale " + std::to_string(scale) : "");
    ts::writeFileAtomic(out + "/README.md", gallery(todo, regen));
  }
  // r goes before ctx: its GL objects with it (RAII).
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  ts::useUtf8Console();
  try {
    return run(argc, argv);
  } catch (const ts::Error& e) {
    std::fprintf(stderr, "make_figures: %s\n", e.what());
    return e.exit_code;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_figures: internal error: %s\n", e.what());
    return 1;
  }
}
