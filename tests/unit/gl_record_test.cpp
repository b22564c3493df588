// tests/unit/gl_record_test.cpp — the GL call recorder (common/gl/gl_record.hpp)
// on the test context: calls are kept with their arguments as a C programmer
// reads them, only while a Recording lives, only on its thread.
#include <gtest/gtest.h>

#include <algorithm>
#include <thread>
#include <vector>

#include "common/gl/context.hpp"

#include "common/gl/gl_record.hpp"
#include "tests/support/gl_test.hpp"

namespace {
using ts::gl::Arg;
using ts::gl::Call;

std::vector<std::string> lines(const std::vector<Call>& calls) {
  std::vector<std::string> out;
  for (const Call& c : calls) out.push_back(ts::gl::formatCall(c));
  return out;
}
bool has(const std::vector<std::string>& v, const std::string& line) {
  return std::find(v.begin(), v.end(), line) != v.end();
}

// Claim: enum names come from the GL headers, the core name before a vendor's.
TEST(GlRecord, EnumNamesFromTheHeaders) {
  EXPECT_STREQ(ts::gl::enumName(GL_LINEAR_MIPMAP_LINEAR), "GL_LINEAR_MIPMAP_LINEAR");
  EXPECT_STREQ(ts::gl::enumName(GL_CLAMP_TO_EDGE), "GL_CLAMP_TO_EDGE");      // not ..._SGIS
  EXPECT_STREQ(ts::gl::enumName(GL_MIRRORED_REPEAT), "GL_MIRRORED_REPEAT");  // not ..._ARB
  unsigned long long v = 0;
  ASSERT_TRUE(ts::gl::enumValue("GL_PERSPECTIVE_CORRECTION_HINT", &v));
  EXPECT_EQ(v, unsigned(GL_PERSPECTIVE_CORRECTION_HINT));
  EXPECT_FALSE(ts::gl::enumValue("GL_NOT_AN_ENUM", &v));
}

// Claim: a recorded call reads back as the C call that was made, enums by
// name, arrays by value, texture data by what it is; the real pointers are
// back when the Recording ends.
TEST(GlRecord, CallsAsCWithTheirValues) {
  ts::test::context();
  auto realBegin = ts::gl::p_glBegin;
  std::vector<Call> calls;
  {
    ts::gl::Recording rec;
    auto recordingBegin = ts::gl::p_glBegin;
    EXPECT_NE(recordingBegin, realBegin);
    GLuint id = 0;
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    unsigned char texels[3 * 2 * 4];
    for (int k = 0; k < 24; ++k) texels[k] = (unsigned char)(k * 10);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 3, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBlendFunc(GL_ONE, GL_ZERO);
    const GLfloat m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5f, 0, 0, 1};
    glLoadMatrixf(m);
    glBegin(GL_TRIANGLES);
    glTexCoord4f(0.9f, 1.1f, 0, 1);
    glVertex3f(-1, 0.25f, 0);
    glEnd();
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport);
    glDeleteTextures(1, &id);
    calls = rec.take();
    ASSERT_FALSE(calls.empty());
    EXPECT_EQ(calls[0].args[1].ints, std::vector<long long>{(long long)(id)});
  }
  // Compared as a copy: gtest takes its arguments by reference, and UBSan's
  // null check misreads a reference to a __thread variable (see gl.hpp).
  auto restoredBegin = ts::gl::p_glBegin;
  EXPECT_EQ(restoredBegin, realBegin);
  std::vector<std::string> l = lines(calls);
  EXPECT_TRUE(has(l, "glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);"));
  EXPECT_TRUE(has(l, "glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);"));  // a number, not GL_NONE
  EXPECT_TRUE(has(l, "glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);"));
  EXPECT_TRUE(has(l, "glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);"));
  EXPECT_TRUE(has(l, "glBlendFunc(GL_ONE, GL_ZERO);"));
  EXPECT_TRUE(has(l, "glBegin(GL_TRIANGLES);"));
  EXPECT_TRUE(has(l, "glTexCoord4f(0.9, 1.1, 0, 1);"));
  EXPECT_TRUE(has(l, "glVertex3f(-1, 0.25, 0);"));
  EXPECT_TRUE(has(l, "glLoadMatrixf((const GLfloat[16]){1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5, 0, 0, 1});"));
  EXPECT_TRUE(has(l, "glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 3, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, "
                     "NULL /* 3x2 GL_RGBA GL_UNSIGNED_BYTE, 24 bytes */);"));
  // The pixels themselves are kept (a standalone program can write them out).
  auto tex = std::find_if(calls.begin(), calls.end(),
                          [](const Call& c) { return std::string(c.name) == "glTexImage2D"; });
  ASSERT_NE(tex, calls.end());
  ASSERT_TRUE(tex->args[8].bytes);
  ASSERT_EQ(tex->args[8].bytes->size(), 24u);
  EXPECT_EQ((*tex->args[8].bytes)[23], 230);
  // A query is marked as one.
  auto get = std::find_if(calls.begin(), calls.end(),
                          [](const Call& c) { return std::string(c.name) == "glGetIntegerv"; });
  ASSERT_NE(get, calls.end());
  EXPECT_TRUE(get->query);
}

// Claim: a sub-image uploaded in place (GL_UNPACK_ROW_LENGTH, _SKIP_PIXELS, _SKIP_ROWS: the tile of a larger
// picture, demos/texture_atlas) is recorded as the texels GL reads, and the unpack values are listed as numbers.
TEST(GlRecord, KeepsTheTexelsTheUnpackStateReads) {
  ts::test::context();
  // A 4 x 3 picture, texel (i, j) = (10 i + j, ...); its 2 x 2 tile at (1, 1).
  unsigned char picture[4 * 3 * 4];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 4; ++c) picture[(j * 4 + i) * 4 + c] = (unsigned char)(10 * i + j + 100 * (c == 3));
  std::vector<Call> calls;
  GLuint id = 0;
  {
    ts::gl::Recording rec;
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 4);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, picture);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    calls = rec.take();
  }
  glDeleteTextures(1, &id);
  std::vector<std::string> l = lines(calls);
  EXPECT_TRUE(has(l, "glPixelStorei(GL_UNPACK_ROW_LENGTH, 4);"));
  EXPECT_TRUE(has(l, "glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);"));
  EXPECT_TRUE(has(l, "glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);"));
  auto sub = std::find_if(calls.begin(), calls.end(),
                          [](const Call& c) { return std::string(c.name) == "glTexSubImage2D"; });
  ASSERT_NE(sub, calls.end());
  ASSERT_TRUE(sub->args[8].bytes);
  std::vector<unsigned char> tile;
  for (int j = 1; j <= 2; ++j)
    for (int i = 1; i <= 2; ++i)
      for (int k = 0; k < 4; ++k) tile.push_back(picture[(j * 4 + i) * 4 + k]);
  EXPECT_EQ(*sub->args[8].bytes, tile);
  // Not the picture's first 2 x 2 x 4 bytes, which a recorder blind to the unpack state would keep.
  EXPECT_NE(*sub->args[8].bytes, std::vector<unsigned char>(picture, picture + 16));
}

// Claim: a 3D texture's texels (glTexImage3D, the slices one after the other) are kept whole, as a 2D texture's
// are, so that an exported program uploads them (it uploaded NULL: a black volume).
TEST(GlRecord, KeepsA3DTexturesSlices) {
  ts::test::context();
  unsigned char volume[2 * 3 * 4 * 4];  // 2 x 3 texels a slice, 4 slices
  for (int k = 0; k < int(sizeof volume); ++k) volume[k] = (unsigned char)(k * 2 + 1);
  std::vector<Call> calls;
  GLuint id = 0;
  {
    ts::gl::Recording rec;
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_3D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 2, 3, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, volume);
    calls = rec.take();
  }
  glDeleteTextures(1, &id);
  auto tex = std::find_if(calls.begin(), calls.end(),
                          [](const Call& c) { return std::string(c.name) == "glTexImage3D"; });
  ASSERT_NE(tex, calls.end());
  ASSERT_TRUE(tex->args[9].bytes);
  EXPECT_EQ(*tex->args[9].bytes, std::vector<unsigned char>(volume, volume + sizeof volume));
}

// Claim: calls on another thread (a measurement on its own context, as the
// window's measurement worker makes) are not the picture's, and nothing is
// kept once the Recording ends.  Each thread has its own table of GL
// pointers (gl.hpp): the other thread loads its own from its own context.
TEST(GlRecord, OnlyThisThreadOnlyWhileAlive) {
  ts::test::context();
  std::vector<Call> calls;
  {
    ts::gl::Recording rec;
    std::string otherError;
    std::thread other([&] {
      try {
        ts::ContextOptions o;
        o.width = o.height = 16;
        auto ctx = ts::createOffscreenContext(ts::Backend::Auto, o);
        glGetError();
        glFlush();
      } catch (const std::exception& e) {
        otherError = e.what();
      }
    });
    other.join();
    ASSERT_EQ(otherError, "");
    glFlush();
    calls = rec.take();
  }
  glFlush();
  ASSERT_EQ(calls.size(), 1u);
  EXPECT_STREQ(calls[0].name, "glFlush");
  EXPECT_FALSE(ts::gl::Recording::active());
}

// Claim: threads record at once, each its own calls (the window's GL pane
// records the frame while the measurement worker records a picture it
// renders on its own context): neither sees the other's calls, and neither's
// end takes the other's wrappers away.
TEST(GlRecord, TwoThreadsRecordAtOnce) {
  ts::test::context();
  std::vector<Call> mine, theirs;
  std::string otherError;
  {
    ts::gl::Recording rec;
    glFlush();
    std::thread other([&] {
      try {
        ts::ContextOptions o;
        o.width = o.height = 16;
        auto ctx = ts::createOffscreenContext(ts::Backend::Auto, o);
        ts::gl::Recording theirRec;
        EXPECT_TRUE(ts::gl::Recording::activeHere());
        glFinish();
        glFinish();
        theirs = theirRec.take();
      } catch (const std::exception& e) {
        otherError = e.what();
      }
    });
    other.join();
    glClear(GL_COLOR_BUFFER_BIT);  // still recorded here: the other's end did not touch this thread's table
    mine = rec.take();
  }
  ASSERT_EQ(otherError, "");
  ASSERT_EQ(mine.size(), 2u);
  EXPECT_STREQ(mine[0].name, "glFlush");
  EXPECT_STREQ(mine[1].name, "glClear");
  ASSERT_EQ(theirs.size(), 2u);
  EXPECT_STREQ(theirs[0].name, "glFinish");
  EXPECT_FALSE(ts::gl::Recording::active());
}

// Claim: recordings nest on one thread (a scene records a picture's render
// inside a recording already running): the inner keeps its calls, the outer
// keeps everything made while it lived, even what the inner took, and the
// real pointers come back only when the outer ends.
TEST(GlRecord, RecordingsNest) {
  ts::test::context();
  std::vector<Call> outer, inner;
  void* real = reinterpret_cast<void*>(ts::gl::p_glFlush);
  {
    ts::gl::Recording o;
    glFlush();
    {
      ts::gl::Recording i;
      glFinish();
      inner = i.take();
    }
    EXPECT_NE(reinterpret_cast<void*>(ts::gl::p_glFlush), real) << "the outer recording still runs";
    glClear(GL_COLOR_BUFFER_BIT);
    outer = o.take();
  }
  EXPECT_EQ(reinterpret_cast<void*>(ts::gl::p_glFlush), real);
  EXPECT_FALSE(ts::gl::Recording::activeHere());
  ASSERT_EQ(inner.size(), 1u);
  EXPECT_STREQ(inner[0].name, "glFinish");
  ASSERT_EQ(outer.size(), 3u);
  EXPECT_STREQ(outer[0].name, "glFlush");
  EXPECT_STREQ(outer[1].name, "glFinish");
  EXPECT_STREQ(outer[2].name, "glClear");
}

// Claim: calls made inside a NotRecorded (a measurement's readback inside a
// recorded render) are made and kept by no Recording, the outer or the
// inner; the recording goes on after it.  The control: the same call before
// and after it is kept.
TEST(GlRecord, NotRecordedCallsAreMadeNotKept) {
  ts::test::context();
  std::vector<Call> outer, inner;
  GLint viewport[4] = {0, 0, 0, 0};
  {
    ts::gl::Recording o;
    glViewport(0, 0, 8, 8);
    {
      ts::gl::Recording i;
      {
        ts::gl::NotRecorded aside;
        glViewport(0, 0, 5, 6);
        glGetIntegerv(GL_VIEWPORT, viewport);  // made: the driver has it
      }
      glClear(GL_COLOR_BUFFER_BIT);
      inner = i.take();
    }
    outer = o.take();
  }
  EXPECT_EQ(viewport[2], 5);
  EXPECT_EQ(viewport[3], 6);
  EXPECT_EQ(lines(inner), std::vector<std::string>{"glClear(GL_COLOR_BUFFER_BIT);"});
  EXPECT_EQ(lines(outer), (std::vector<std::string>{"glViewport(0, 0, 8, 8);", "glClear(GL_COLOR_BUFFER_BIT);"}));
  EXPECT_FALSE(ts::gl::Recording::activeHere());
}

// Claim: with recording off the cost is nothing at all: once a Recording
// ends, every pointer of the table is the very pointer it was before, so a
// call goes straight to the driver (bench_figures' render_after_recording
// times it beside render).
TEST(GlRecord, EndingARecordingRestoresEveryPointer) {
  ts::test::context();
  std::vector<void*> before, during, after;
#define TS_TAKE(name) before.push_back(reinterpret_cast<void*>(ts::gl::p_##name));
  TS_GL_FUNCTIONS(TS_TAKE)
#undef TS_TAKE
  {
    ts::gl::Recording rec;
#define TS_TAKE(name) during.push_back(reinterpret_cast<void*>(ts::gl::p_##name));
    TS_GL_FUNCTIONS(TS_TAKE)
#undef TS_TAKE
  }
#define TS_TAKE(name) after.push_back(reinterpret_cast<void*>(ts::gl::p_##name));
  TS_GL_FUNCTIONS(TS_TAKE)
#undef TS_TAKE
  EXPECT_EQ(before, after);
  size_t swapped = 0;
  for (size_t i = 0; i < before.size(); ++i) swapped += before[i] != during[i];
  EXPECT_EQ(swapped, before.size()) << "while recording, every call goes through a wrapper";
}
}  // namespace
