#include "common/gl/figure.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "common/gl/context.hpp"
#include "common/core/error.hpp"
#include "common/gl/gl_listing.hpp"
#include "common/gl/render.hpp"

namespace ts {
Rendered renderScene(Scene& scene, Renderer& r, int width, int height, bool record) {
  Context& ctx = r.context();
  Rendered out;
  // The measure pass starts from the figure's own context size and viewport,
  // not the previous figure's: what it records (a render target restores the
  // viewport it found) is then the same whichever figures ran before.
  if (ctx.width() != width || ctx.height() != height) ctx.resize(width, height);
  glViewport(0, 0, width, height);
  out.measurements = scene.measure(r);  // may resize the target for itself
  if (ctx.width() != width || ctx.height() != height) ctx.resize(width, height);
  out.frame = scene.build(width, height, out.measurements);
  if (record) out.calls = recordPicture(r, out.frame);  // the same picture, drawn once more
  out.image = r.render(out.frame);
  return out;
}

std::string glListingFile(const Rendered& got, const std::string& state) {
  // The frame's calls read where they are, not copied into the last section:
  // a mesh drawn call by call is hundreds of thousands of them.  (A pointer
  // that owns nothing: got outlives the listing.)
  std::vector<CallSection> sections = pictureSections(got.frame, {});
  sections.back().calls = gl::CallList(gl::CallList(), &got.calls);
  return listingText(listing(sections, nullptr, 3),
                     "The OpenGL calls that draw this picture, recorded as they were made by\n"
                     "       " +
                         state +
                         " --gl-listing FILE\n"
                         "   Object names are numbered in order of creation; queries (glGet*) are left out;\n"
                         "   each glBegin shows its first 3 vertices. Every line is C.");
}

void checkWritable(const std::string& path) {
  if (path.empty()) throw Error("empty output path");
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw Error("cannot write " + path + ": it is a directory");
  std::string probe = path + ".tmp-" + std::to_string(::getpid());
  std::FILE* f = std::fopen(probe.c_str(), "wb");
  if (!f) throw Error("cannot write " + path + ": " + std::strerror(errno));
  std::fclose(f);
  std::remove(probe.c_str());
}

// Quotes an argument for the shell the student types into when it needs it:
// single quotes for a POSIX shell; double quotes on Windows, where both
// cmd.exe and PowerShell read them (and a program runs from its own folder,
// the zip's layout, rather than from build/bin).
#ifdef _WIN32
static std::string shellQuote(const std::string& a) {
  if (!a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_=./\\,:+") ==
                        std::string::npos)
    return a;
  std::string q = "\"";
  for (char c : a) q += c == '"' ? std::string("\\\"") : std::string(1, c);
  return q + "\"";
}
static const char* const kProgramPrefix = "";
static const char* const kProgramSuffix = ".exe";
#else
static std::string shellQuote(const std::string& a) {
  if (!a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_=./,:+") ==
                        std::string::npos)
    return a;
  std::string q = "'";
  for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}
static const char* const kProgramPrefix = "build/bin/";
static const char* const kProgramSuffix = "";
#endif

std::string stateCommand(const std::string& demo, int w, int h, const std::vector<std::string>& flags) {
  std::string c = kProgramPrefix + demo + kProgramSuffix + " --size " + std::to_string(w) + "x" + std::to_string(h);
  for (const auto& f : flags) c += " " + shellQuote(f);
  return c;
}

std::string figureCommand(const std::string& demo, const std::string& png, int w, int h,
                          const std::vector<std::string>& flags) {
  std::string c = kProgramPrefix + demo + kProgramSuffix + " --png " + shellQuote(png) + " --size " +
                  std::to_string(w) + "x" + std::to_string(h);
  for (const auto& f : flags) c += " " + shellQuote(f);
  return c;
}
}  // namespace ts
