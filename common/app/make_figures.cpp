// make_figures — renders every registered book figure into one folder, in
// one process with one offscreen context (textures and shaders are shared
// between figures), and writes the gallery README.md beside them.
//
//   make_figures [--out DIR] [--backend auto|osmesa|egl] [--scale F] [--only ID] [--list]
#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "common/gl/context.hpp"
#include "common/core/error.hpp"
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
};

std::string gallery(const std::vector<Entry>& entries, const std::string& regenerate) {
  std::string md =
      "# Book figures\n\n"
      "Every image here is made by the suite; none is drawn by hand. Regenerate all of them with\n\n"
      "    " + regenerate + "\n\n"
      "Each PNG has a sidecar `.json` beside it with every parameter needed to recompute it without OpenGL:\n"
      "size, projection and modelview matrices, textures (how they were made, filters, wrap modes), and every\n"
      "vertex with its (s,t,r,q). The measured numbers below are the figure's claim, checked by the tests.\n\n";
  for (const Entry& e : entries) {
    md += "## " + e.spec.bookNumber + ": `" + e.spec.id + "`\n\n";
    md += "![" + e.spec.bookNumber + "](" + e.spec.id + ".png)\n\n";
    md += e.spec.caption + "\n\n";
    md += "Source: [`demos/" + e.demo + "/" + e.demo + ".cpp`](../demos/" + e.demo + "/" + e.demo + ".cpp). ";
    md += "The OpenGL calls that draw it: [`" + e.spec.id + ".gl.txt`](" + e.spec.id + ".gl.txt). ";
    md += "Make just this one:\n\n    " + e.command + "\n\n";
    md += "| measured | value | meaning |\n|---|---|---|\n";
    for (const auto& m : e.measurements) {
      char v[32];
      std::snprintf(v, sizeof v, "%.3f", m.value);
      std::string meaning;
      for (char c : m.meaning) meaning += c == '|' ? std::string("\\|") : std::string(1, c);
      md += "| `" + m.name + "` | " + v + " | " + meaning + " |\n";
    }
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

int run(int argc, char** argv) {
  std::string out = "book_figures", backend = "auto", only;
  double scale = 1.0;
  bool list = false, exportPrograms = false;
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
    else if (a == "--scale") {
      std::string v = need();
      char* end = nullptr;
      scale = std::strtod(v.c_str(), &end);
      if (v.empty() || *end || !(scale > 0) || scale > 16) throw ts::Error("--scale: '" + v + "' is not in (0, 16]");
    } else if (a == "--help" || a == "-h") {
      std::printf("usage: make_figures [--out DIR] [--backend auto|osmesa|egl] [--scale F] [--only ID] [--list] [--export-c]\n"
                  "Renders every registered book figure (PNG + sidecar JSON + GL listing) and the gallery README.md\n"
                  "into DIR (default book_figures). --scale multiplies every figure's size. --only ID[,ID...]: just\n"
                  "these figures or every figure of these demos (no gallery). --export-c: also each figure as a\n"
                  "standalone C program, DIR/<id>.c and DIR/<id>.texels (see --export-c of the demos).\n");
      return 0;
    } else throw ts::Error("unknown argument '" + a + "' (see --help)");
  }
  ts::Backend b = ts::parseBackend(backend);
  if (b == ts::Backend::Window) throw ts::Error("figures render offscreen: --backend osmesa, egl or auto");

  std::vector<Entry> todo;
  for (const auto& reg : ts::sceneRegistry())
    for (const auto& spec : reg.make()->figures()) {
      if (!only.empty() && !selected(only, spec.id, reg.id)) continue;
      Entry e{spec, reg.id, "", {}};
      e.spec.width = std::max(1, int(std::lround(spec.width * scale)));
      e.spec.height = std::max(1, int(std::lround(spec.height * scale)));
      if (e.spec.width > ts::kMaxImageDimension || e.spec.height > ts::kMaxImageDimension)
        throw ts::Error("--scale " + std::to_string(scale) + " makes " + spec.id + " larger than 16384 pixels");
      todo.push_back(e);
    }
  if (list) {
    for (const auto& e : todo) std::printf("%-28s %-24s %dx%d  demos/%s\n", e.spec.id.c_str(), e.spec.bookNumber.c_str(),
                                           e.spec.width, e.spec.height, e.demo.c_str());
    return 0;
  }
  if (todo.empty()) throw ts::Error("no figure or demo named '" + only + "' (see --list)");
  struct stat st;
  if (::stat(out.c_str(), &st) != 0 && ::mkdir(out.c_str(), 0777) != 0)
    throw ts::Error("cannot create " + out + ": " + std::strerror(errno));
  ts::checkWritable(out + "/README.md");

  ts::ContextOptions co;
  co.verbose = true;
  for (const auto& reg : ts::sceneRegistry()) co.accumBuffer |= reg.make()->wantsAccumBuffer();
  auto ctx = ts::createOffscreenContext(b, co);
  ts::Renderer r(*ctx);
  std::printf("rendering %zu figures into %s/ with %s\n", todo.size(), out.c_str(), ctx->describe().c_str());
  // One scene per demo for all its figures, each from the defaults and its
  // own flags: what a scene keeps between measurements (the parallax table,
  // the jitter images) serves every figure of the same state.
  struct Demo {
    std::unique_ptr<ts::Scene> scene;
    ts::Options opts;
  };
  std::map<std::string, Demo> demos;
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
    opts.parse(e.spec.flags);
    ts::Rendered got = ts::renderScene(*scene, r, e.spec.width, e.spec.height, true);
    std::string png = out + "/" + e.spec.id + ".png", json = out + "/" + e.spec.id + ".json";
    std::string listing = out + "/" + e.spec.id + ".gl.txt";
    std::vector<std::string> flags = {"--json", json};
    flags.insert(flags.end(), e.spec.flags.begin(), e.spec.flags.end());
    e.command = ts::figureCommand(e.demo, png, e.spec.width, e.spec.height, flags);
    e.measurements = got.measurements;
    ts::SidecarInfo info{e.spec.id, e.spec.bookNumber, e.spec.caption, e.demo, e.command, opts.state(), got.measurements,
                         ts::gl::rendererString() + " | " + ts::gl::versionString()};
    ts::writePng(png, got.image);
    ts::writeFileAtomic(json, ts::sidecarJson(got.frame, info));
    ts::writeFileAtomic(listing, ts::glListingFile(got, ts::stateCommand(e.demo, e.spec.width, e.spec.height, e.spec.flags)));
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
  }
  if (only.empty()) {
    std::string regen = "scripts/figures.sh" + std::string(scale != 1.0 ? " --scale " + std::to_string(scale) : "");
    ts::writeFileAtomic(out + "/README.md", gallery(todo, regen));
  }
  // r goes before ctx: its GL objects with it (RAII).
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
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
