// tests/reliability/reliability_test.cpp — nothing a user feeds the
// suite may crash it.  Claims, each a test below:
//   * the committed corpus is exactly what corpus_gen.hpp makes;
//   * every good file (PNG: grey 1/4/8/16-bit, grey+alpha, palette with tRNS,
//     RGB, RGBA, 8 and 16 bits, interlaced; 24-bit BMP bottom-up and
//     top-down; 32-bit BMP with alpha and bitfields; odd sizes) decodes to
//     exactly the expected RGBA8 pixels, JPEG within its case's tolerance;
//   * every malformed file throws one ts::Error line "<path>: ..." naming
//     what is wrong (exit status 2), as do a missing file, a directory, a
//     FIFO, a device and a file without read permission;
//   * every prefix of a good PNG and BMP, and every single-byte change of a
//     small PNG and BMP, either decodes or throws ts::Error (never crashes);
//   * files found by fuzzing (corpus/regressions/) decode or throw ts::Error;
//   * GL: a non-power-of-two texture is sampled texel for texel; a shader
//     that does not compile names the C++ file and line; a GL error names
//     the stage and, with KHR_debug, the driver's words.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <dirent.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>

#include "common/core/bmp.hpp"
#include "common/core/error.hpp"
#include "common/core/textures.hpp"
#include "corpus_gen.hpp"
#include "tests/support/gl_test.hpp"

namespace {
const std::string kCorpus = "tests/reliability/corpus";

corpus::Bytes readAll(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return corpus::Bytes(std::istreambuf_iterator<char>(f), {});
}
void writeAll(const std::string& path, const corpus::Bytes& b) {
  std::ofstream f(path, std::ios::binary);
  f.write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
}
std::vector<std::string> listDir(const std::string& dir) {
  std::vector<std::string> out;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d))
      if (e->d_name[0] != '.') out.push_back(e->d_name);
    closedir(d);
  }
  std::sort(out.begin(), out.end());
  return out;
}

struct TempDir {
  std::string path;
  TempDir() {
    char t[] = "/tmp/ts_reliability.XXXXXX";
    path = mkdtemp(t);
    chmod(path.c_str(), 0755);  // so an unprivileged child can reach files in it
  }
  ~TempDir() { std::system(("rm -rf '" + path + "'").c_str()); }
  std::string operator/(const std::string& n) const { return path + "/" + n; }
};

// The one line a bad file must produce: starts with the path, names the
// problem, no newline, exit status 2.  Returns "" when it holds.
std::string checkError(const std::function<void()>& f, const std::string& path, const std::string& phrase) {
  try {
    f();
  } catch (const ts::Error& e) {
    std::string m = e.what();
    if (m.rfind(path + ": ", 0) != 0) return "message does not start with the path: " + m;
    if (m.find('\n') != std::string::npos) return "message has more than one line: " + m;
    if (!phrase.empty() && m.find(phrase) == std::string::npos) return "message lacks '" + phrase + "': " + m;
    if (e.exit_code != ts::kExitUsage) return "exit code " + std::to_string(e.exit_code) + ": " + m;
    return "";
  } catch (const std::exception& e) {
    return std::string("not a ts::Error: ") + e.what();
  }
  return "no error for a bad file";
}
}  // namespace

TEST(Corpus, CommittedFilesMatchTheGenerator) {
  std::vector<corpus::Case> cases = corpus::makeCases();
  std::string manifest;
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_TRUE(readAll(kCorpus + "/" + c.name) == c.bytes)
        << "regenerate with: build/bin/reliability_tool corpus " << kCorpus;
    manifest += c.name + (c.good ? "\tok\n" : "\terror\t" + c.error + "\n");
  }
  corpus::Bytes m = readAll(kCorpus + "/MANIFEST");
  EXPECT_EQ(std::string(m.begin(), m.end()), manifest);
  // Nothing in the folder that the generator does not make (but regressions/).
  std::vector<std::string> want{"MANIFEST", "regressions"};
  for (const auto& c : cases) want.push_back(c.name);
  std::sort(want.begin(), want.end());
  EXPECT_EQ(listDir(kCorpus), want);
  size_t good = 0, bad = 0;
  for (const auto& c : cases) (c.good ? good : bad)++;
  std::printf("corpus: %zu well-formed files, %zu malformed files\n", good, bad);
  EXPECT_GE(bad, 40u);
}

int channelDiff(ts::Rgba a, ts::Rgba b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b), std::abs(a.a - b.a)});
}

TEST(Corpus, GoodFilesDecodeExactly) {
  for (const auto& c : corpus::makeCases()) {
    if (!c.good) continue;
    SCOPED_TRACE(c.name);
    std::string path = kCorpus + "/" + c.name;
    ts::Image img;
    try {
      img = ts::readImage(path);
    } catch (const ts::Error& e) {
      ADD_FAILURE() << e.what();
      continue;
    }
    ASSERT_EQ(img.width, c.expect.width);
    ASSERT_EQ(img.height, c.expect.height);
    int wrong = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        if (channelDiff(img.at(x, y), c.expect.at(x, y)) > c.tolerance && wrong++ < 3) {
          ts::Rgba a = img.at(x, y), b = c.expect.at(x, y);
          ADD_FAILURE() << "pixel (" << x << "," << y << ") is " << int(a.r) << "," << int(a.g) << "," << int(a.b)
                        << "," << int(a.a) << " want " << int(b.r) << "," << int(b.g) << "," << int(b.b) << ","
                        << int(b.a);
        }
    EXPECT_EQ(wrong, 0);
    // As a texture: kept at its own size, top row of the picture at t = 1.
    ts::TextureDesc t = ts::fileTexture(path);
    ASSERT_EQ(t.image->width, c.expect.width);
    EXPECT_LE(channelDiff(t.image->at(0, t.image->height - 1), c.expect.at(0, 0)), c.tolerance);
  }
}

TEST(Corpus, BadFilesGiveOneLineNamingTheFile) {
  for (const auto& c : corpus::makeCases()) {
    if (c.good) continue;
    std::string path = kCorpus + "/" + c.name;
    std::string why = checkError([&] { ts::readImage(path); }, path, c.error);
    EXPECT_EQ(why, "") << c.name;
    // The texture loader says the same.
    EXPECT_EQ(checkError([&] { ts::fileTexture(path); }, path, c.error), "") << c.name;
  }
}

TEST(Corpus, FuzzRegressionsDecodeOrFailCleanly) {
  std::string dir = kCorpus + "/regressions";
  std::vector<std::string> files = listDir(dir);
  for (const auto& n : files) {
    std::string path = dir + "/" + n;
    try {
      ts::readImage(path);
    } catch (const ts::Error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
    }
  }
  std::printf("%zu fuzz regression files\n", files.size());
}

TEST(Files, MissingDirectoryFifoDevice) {
  TempDir t;
  EXPECT_EQ(checkError([&] { ts::readImage(t / "missing.png"); }, t / "missing.png", "No such file"), "");
  EXPECT_EQ(checkError([&] { ts::readImage(t.path); }, t.path, "is a directory"), "");
  ASSERT_EQ(mkfifo((t / "fifo.png").c_str(), 0644), 0);  // must not hang waiting for a writer
  EXPECT_EQ(checkError([&] { ts::readImage(t / "fifo.png"); }, t / "fifo.png", "not a regular file"), "");
  EXPECT_EQ(checkError([&] { ts::readImage("/dev/zero"); }, "/dev/zero", "not a regular file"), "");
  EXPECT_EQ(checkError([&] { ts::readImage("/dev/null"); }, "/dev/null", "not a regular file"), "");
}

// Root reads anything, so as root the check runs in a child that has given
// up root (setuid to nobody, 65534); as anyone else it runs directly.
TEST(Files, NoReadPermission) {
  TempDir t;
  std::string path = t / "secret.png";
  writeAll(path, corpus::makePng(4, 4, 8, 2));
  ASSERT_EQ(chmod(path.c_str(), 0), 0);
  if (geteuid() != 0) {
    EXPECT_EQ(checkError([&] { ts::readImage(path); }, path, "Permission denied"), "");
    return;
  }
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    close(fds[0]);
    std::string why;
    if (setgid(65534) != 0 || setuid(65534) != 0) why = "could not drop root";
    else why = checkError([&] { ts::readImage(path); }, path, "Permission denied");
    if (write(fds[1], why.data(), why.size()) < 0) _exit(3);
    _exit(why.empty() ? 0 : 1);
  }
  close(fds[1]);
  char buf[1024];
  std::string why;
  ssize_t n;
  while ((n = read(fds[0], buf, sizeof buf)) > 0) why.append(buf, size_t(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "the child crashed";
  EXPECT_EQ(WEXITSTATUS(status), 0) << why;
}

// Every prefix of a good file is refused; every one-byte change either
// decodes or is refused: never a crash (ASan/UBSan builds check the rest).
TEST(Mutations, EveryPrefixAndEveryByteFlip) {
  struct Seed {
    const char* name;
    corpus::Bytes bytes;
  } seeds[] = {{"rgba8_interlaced.png", corpus::makePng(9, 7, 8, 6, 1)},
               {"palette4.png", corpus::makePng(9, 7, 4, 3)},
               {"grey16.png", corpus::makePng(5, 3, 16, 0)},
               {"bmp24.bmp", ts::encodeBmp(corpus::rgbPicture(5, 3))}};
  size_t tried = 0, refused = 0;
  for (const Seed& s : seeds) {
    for (size_t keep = 0; keep < s.bytes.size(); ++keep) {
      ++tried;
      std::string why = checkError([&] { ts::decodeImage(s.bytes.data(), keep, s.name); }, s.name, "");
      EXPECT_EQ(why, "") << s.name << " cut to " << keep << " bytes";
      refused += why.empty();
    }
    for (size_t i = 0; i < s.bytes.size(); ++i)
      for (uint8_t x : {uint8_t(0x01), uint8_t(0x80), uint8_t(0xff)}) {
        corpus::Bytes b = s.bytes;
        b[i] ^= x;
        ++tried;
        try {
          ts::Image img = ts::decodeImage(b.data(), b.size(), s.name);
          EXPECT_FALSE(img.empty());
        } catch (const ts::Error& e) {
          ++refused;
          EXPECT_EQ(std::string(e.what()).rfind(std::string(s.name) + ": ", 0), 0u) << e.what();
        }
      }
  }
  std::printf("%zu mutated inputs, %zu refused with one line, the rest decoded\n", tried, refused);
}

TEST(Sizes, LimitsAreCheckedBeforeAllocating) {
  EXPECT_EQ(ts::checkImageSize(16384, 4096), "");
  EXPECT_NE(ts::checkImageSize(16384, 4097), "");  // over 64 Mi pixels
  EXPECT_NE(ts::checkImageSize(16385, 1), "");
  EXPECT_NE(ts::checkImageSize(0, 1), "");
  EXPECT_NE(ts::checkImageSize(1, 0), "");
  EXPECT_NE(ts::checkImageSize(uint64_t(1) << 40, uint64_t(1) << 40), "");
}

TEST(Sizes, ResizeBilinear) {
  ts::Image src(2, 1);
  src.set(0, 0, {0, 0, 0, 255});
  src.set(1, 0, {200, 100, 50, 255});
  ts::Image dst = ts::resizeBilinear(src, 4, 1);
  // Centres at 0.25 - 0.5 = -0.25 (clamped to 0), 0.25, 0.75, 1.25 (clamped).
  EXPECT_EQ(dst.at(0, 0), (ts::Rgba{0, 0, 0, 255}));
  EXPECT_EQ(dst.at(1, 0), (ts::Rgba{50, 25, 13, 255}));
  EXPECT_EQ(dst.at(2, 0), (ts::Rgba{150, 75, 38, 255}));
  EXPECT_EQ(dst.at(3, 0), (ts::Rgba{200, 100, 50, 255}));
}

TEST(ShaderLog, FileAndLine) {
  std::string log = "0:3(12): error: `foo' undeclared\n0:4(1): error: syntax error\n";
  EXPECT_EQ(ts::formatShaderLog(log, "demos/x/x.cpp", 51, "fragment"),
            "demos/x/x.cpp:53:12: error: `foo' undeclared; demos/x/x.cpp:54:1: error: syntax error");
  EXPECT_EQ(ts::formatShaderLog("0(7) : error C0000: bad\n", "a.cpp", 0, "vertex"),
            "a.cpp: vertex shader line 7: error C0000: bad");
  EXPECT_EQ(ts::formatShaderLog("", "a.cpp", 0, "vertex"), "a.cpp: (the driver gave no log)");
}

// ------------------------------------------------------------------ GL
namespace {
ts::Frame fullScreenQuad(int w, int h, ts::TextureDesc tex) {
  ts::Frame f;
  f.width = w;
  f.height = h;
  f.textures.push_back(std::move(tex));
  ts::Panel p;
  p.id = "quad";
  p.viewport = {0, 0, w, h};
  ts::Batch b;
  b.texture = 0;
  auto v = [](float x, float y, float s, float t) {
    ts::Vertex q;
    q.pos = {x, y, 0};
    q.tex = {s, t, 0, 1};
    return q;
  };
  b.vertices = {v(-1, -1, 0, 0), v(1, -1, 1, 0), v(1, 1, 1, 1), v(-1, -1, 0, 0), v(1, 1, 1, 1), v(-1, 1, 0, 1)};
  p.batches.push_back(b);
  f.panels.push_back(p);
  return f;
}
}  // namespace

// A 37x23 file texture (not a power of two) drawn 1:1 with GL_NEAREST gives
// back every texel: used directly, not resized, not shifted.
TEST(Gl, NonPowerOfTwoTextureIsSampledExactly) {
  std::string path = kCorpus + "/good_rgb8_1x1.png";  // (just to be sure the corpus is there)
  ASSERT_EQ(access(path.c_str(), R_OK), 0);
  ts::TextureDesc t = ts::fileTexture(kCorpus + "/good_bmp24_topdown_5x3.bmp");
  ts::TextureDesc big = ts::fileTexture(kCorpus + "/good_rgba8_37x23.png");
  for (ts::TextureDesc* tex : {&t, &big}) {
    tex->minFilter = tex->magFilter = GL_NEAREST;
    ts::Image want = *tex->image;
    want.flipVertical();  // the picture as the file shows it
    for (auto& px : want.pixels) (void)px;
    ts::Frame f = fullScreenQuad(want.width, want.height, *tex);
    ts::Image got = ts::test::renderer().render(f, false);
    int wrong = 0;
    for (int y = 0; y < want.height; ++y)
      for (int x = 0; x < want.width; ++x) {
        ts::Rgba a = got.at(x, y), b = want.at(x, y);
        b.a = 255;  // GL_REPLACE writes the texel's alpha; compare colour only
        a.a = 255;
        wrong += a != b;
      }
    EXPECT_EQ(wrong, 0) << tex->params[0].second;
  }
}

// The path for a context without non-power-of-two textures, taken on real GL
// (TS_GL_NO_NPOT=1): the 37x23 texture is resized bilinearly to 64x32, the
// renderer says so on stderr, and drawn 1:1 with GL_NEAREST every pixel is
// the resized texel its centre falls in — a stated filter, not a silent one.
TEST(Gl, WithoutNpotTheTextureIsResizedAndSaysSo) {
  ts::TextureDesc tex = ts::fileTexture(kCorpus + "/good_rgba8_37x23.png");
  tex.params.push_back({"case", "no-npot"});  // a key of its own: not the cached direct upload
  tex.minFilter = tex.magFilter = GL_NEAREST;
  const int W = tex.image->width, H = tex.image->height;
  ts::Image resized = ts::resizeBilinear(*tex.image, 64, 32);  // texture rows: row 0 = t = 0
  setenv("TS_GL_NO_NPOT", "1", 1);
  testing::internal::CaptureStderr();
  ts::Image got;
  try {
    got = ts::test::renderer().render(fullScreenQuad(W, H, tex), false);
  } catch (...) {
    testing::internal::GetCapturedStderr();
    unsetenv("TS_GL_NO_NPOT");
    throw;
  }
  std::string err = testing::internal::GetCapturedStderr();
  unsetenv("TS_GL_NO_NPOT");
  EXPECT_NE(err.find("resized bilinearly to 64x32"), std::string::npos) << "stderr: " << err;
  int wrong = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      // Output row y (top) is t = (H - y - 0.5) / H; the texel row under it.
      // A centre exactly on a texel boundary (x = 18, y = 11 here) may take
      // either texel: any legal one is accepted.
      double sx = (x + 0.5) * 64 / W, sy = (H - y - 0.5) * 32 / H;
      ts::Rgba a = got.at(x, y);
      a.a = 255;
      bool ok = false;
      for (int tx : {int(sx), int(std::ceil(sx)) - 1})
        for (int ty : {int(sy), int(std::ceil(sy)) - 1}) {
          if (tx < 0 || ty < 0) continue;
          ts::Rgba b = resized.at(tx, ty);
          b.a = 255;
          ok = ok || a == b;
        }
      wrong += !ok;
    }
  EXPECT_EQ(wrong, 0);
  // And it is not the direct upload: the 37x23 texels themselves differ somewhere.
  ts::Image direct = *tex.image;
  int same = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      ts::Rgba a = got.at(x, y), b = direct.at(x, H - 1 - y);
      a.a = b.a = 255;
      same += a == b;
    }
  EXPECT_LT(same, W * H);
}

TEST(Gl, ShaderCompileErrorNamesFileAndLine) {
  ts::TextureDesc t = ts::checkerboard(8, 2);
  ts::Frame f = fullScreenQuad(16, 16, t);
  // This file is the "file" of the program, and the source below is found
  // in it, so the error must point at the line with `undeclared_name`.
  const char* fs = R"(#version 120
void main() {
  gl_FragColor = vec4(undeclared_name);
})";
  f.programs.push_back(
      {"broken", {"tests/reliability/reliability_test.cpp", "void main() { gl_Position = ftransform(); }", fs}});
  f.panels[0].batches[0].program = "broken";
  std::string msg;
  try {
    ts::test::renderer().render(f, false);
  } catch (const ts::Error& e) {
    msg = e.what();
  }
  ASSERT_FALSE(msg.empty()) << "a broken shader rendered";
  // Which line of this file holds `undeclared_name`?
  corpus::Bytes src = readAll("tests/reliability/reliability_test.cpp");
  std::string text(src.begin(), src.end());
  size_t at = text.find("gl_FragColor = vec4(undeclared_name)");
  int line = 1 + int(std::count(text.begin(), text.begin() + long(at), '\n'));
  EXPECT_NE(msg.find("tests/reliability/reliability_test.cpp:" + std::to_string(line) + ":"), std::string::npos) << msg;
  EXPECT_NE(msg.find("undeclared_name"), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  ts::test::renderer().release();
}

TEST(Gl, ErrorsNameTheStageAndTheDriversWords) {
  ts::test::context();
  bool debug = ts::gl::enableDebugOutput();
  glBindTexture(GL_TEXTURE_2D, 0);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, -5, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  std::string msg;
  try {
    ts::gl::check("a deliberately bad glTexImage2D");
  } catch (const ts::Error& e) {
    msg = e.what();
  }
  EXPECT_NE(msg.find("GL_INVALID_VALUE after a deliberately bad glTexImage2D"), std::string::npos) << msg;
  if (debug) EXPECT_NE(msg.find("(driver: "), std::string::npos) << msg;
  else std::printf("no KHR_debug on %s: the driver's words are not available\n", ts::gl::versionString().c_str());
  EXPECT_NO_THROW(ts::gl::check("nothing"));  // the error was consumed
}
