#include "common/gl/export_c.hpp"

#include <cstring>
#include <map>
#include <set>

#include "common/core/error.hpp"
#include "common/gl/figure.hpp"
#include "common/gl/gl_listing.hpp"
#include "common/core/image.hpp"

namespace ts {
namespace {
bool is(const gl::Call& c, const char* name) { return std::strcmp(c.name, name) == 0; }

gl::Arg code(const std::string& text) {
  gl::Arg a;
  a.kind = gl::Arg::Kind::Code;
  a.text = {text};
  return a;
}

// The header comment's text: "*/" cannot appear inside it.
std::string commentSafe(std::string s) {
  for (size_t p; (p = s.find("*/")) != std::string::npos;) s.replace(p, 2, "* /");
  return s;
}
std::string wrap(std::string text, const std::string& prefix, size_t width = 92) {
  // A single newline in the source text is a space; a blank line a paragraph.
  for (size_t k = 0; k + 1 < text.size(); ++k)
    if (text[k] == '\n' && text[k + 1] != '\n' && (k == 0 || text[k - 1] != '\n')) text[k] = ' ';
  std::string out, line;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find_first_of(" \n", pos);
    if (end == std::string::npos) end = text.size();
    std::string word = text.substr(pos, end - pos);
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += prefix + line + "\n";
      line.clear();
    }
    if (!word.empty()) line += (line.empty() ? "" : " ") + word;
    if (end < text.size() && text[end] == '\n') {
      out += prefix + line + "\n";
      line.clear();
    }
    pos = end + 1;
  }
  if (!line.empty()) out += prefix + line + "\n";
  return out;
}

struct Generator {
  const Frame& frame;
  std::vector<std::string> init, display, arrays;
  std::vector<unsigned char> texels;
  std::set<long long> textures;  // texture numbers made in the recording
  long long maxTexture = 0, maxObject = 0;
  int locations = 0, batches = 0;
  std::map<std::pair<long long, long long>, int> locationOf;  // (program, GL location) -> location[j]
  long long program = 0;
  std::string lastBind;  // the last glBindTexture statement, for init's uploads
  bool bindInInit = false;

  std::string text(const gl::Call& c) { return "  " + gl::formatCall(c, true); }

  // Comments from the Frame: the renderer sets one viewport for the whole
  // frame, then one per panel in the Frame's order, then one for the labels;
  // inside a panel each batch starts by enabling or disabling GL_TEXTURE_2D.
  // Counting them (rather than matching viewport numbers) names panels that
  // share a rectangle correctly.
  int viewports = 0, panel = -1;
  size_t batch = 0;
  void commentViewport() {
    int k = viewports++;
    if (k == 0) return;  // run() opens display() with the whole frame's comment
    display.push_back("");
    if (size_t(k) <= frame.panels.size()) {
      panel = k - 1;
      batch = 0;
      display.push_back("  /* panel \"" + commentSafe(frame.panels[size_t(panel)].id) + "\" */");
    } else {
      panel = -1;
      display.push_back("  /* the labels: quads of the font texture, in pixels */");
    }
  }
  void commentBatch(const gl::Call& c) {
    if (panel < 0 || c.args.empty() || c.args[0].i != GL_TEXTURE_2D) return;
    const Panel& p = frame.panels[size_t(panel)];
    if (batch >= p.batches.size()) return;
    const std::string& role = p.batches[batch].role;
    display.push_back("  /* panel \"" + commentSafe(p.id) + "\": batch " +
                      (role.empty() ? std::to_string(batch + 1) : "\"" + commentSafe(role) + "\"") + " */");
    ++batch;
  }

  // glBegin ... glEnd: verbatim when short or irregular; else the vertex
  // data in an array and a loop making the same calls per vertex.
  void block(const std::vector<gl::Call>& body, const gl::Call& begin, const gl::Call& end) {
    std::vector<std::vector<const gl::Call*>> groups(1);
    for (const gl::Call& c : body) {
      groups.back().push_back(&c);
      if (std::strncmp(c.name, "glVertex", 8) == 0) groups.emplace_back();
    }
    if (groups.back().empty()) groups.pop_back();
    bool regular = groups.size() >= 8;
    for (size_t g = 0; regular && g < groups.size(); ++g) {
      regular = groups[g].size() == groups[0].size();
      for (size_t k = 0; regular && k < groups[g].size(); ++k) {
        regular = is(*groups[g][k], groups[0][k]->name);
        for (const gl::Arg& a : groups[g][k]->args) regular = regular && a.kind == gl::Arg::Kind::Float;
      }
    }
    if (!regular) {
      display.push_back(text(begin));
      for (const gl::Call& c : body) display.push_back("  " + text(c));
      display.push_back(text(end));
      return;
    }
    size_t row = 0;
    for (const gl::Call* c : groups[0]) row += c->args.size();
    std::string name = "vertices" + std::to_string(++batches);
    std::string a = "/* " + std::to_string(groups.size()) + " vertices of display()'s " + begin.name + "(" +
                    gl::formatCall(begin).substr(8, std::string::npos) + " loop: ";
    a.erase(a.find(";"), 1);
    for (const gl::Call* c : groups[0]) a += std::string(c->name) + " ";
    a.pop_back();
    a += " */\nstatic const GLfloat " + name + "[" + std::to_string(groups.size()) + "][" + std::to_string(row) +
         "] = {\n";
    for (const auto& g : groups) {
      a += "  {";
      bool first = true;
      for (const gl::Call* c : g)
        for (const gl::Arg& x : c->args) {
          a += (first ? "" : ", ") + gl::floatLiteral(x.f);
          first = false;
        }
      a += "},\n";
    }
    a += "};";
    arrays.push_back(a);
    display.push_back(text(begin));
    display.push_back("  for (size_t i = 0; i < " + std::to_string(groups.size()) + "; ++i) {");
    size_t col = 0;
    for (const gl::Call* c : groups[0]) {
      std::string line = "    " + std::string(c->name) + "(";
      for (size_t k = 0; k < c->args.size(); ++k) line += (k ? ", " : "") + name + "[i][" + std::to_string(col++) + "]";
      display.push_back(line + ");");
    }
    display.push_back("  }");
    display.push_back(text(end));
  }

  void run(const std::vector<gl::Call>& calls) {
    display.push_back("  /* the whole frame: clear, and the state every panel shares */");
    for (size_t i = 0; i < calls.size(); ++i) {
      gl::Call c = calls[i];
      if (c.query) continue;
      // The program's own window or buffer is its target: the suite's
      // framebuffer binds are not part of the picture.
      if (is(c, "glBindFramebuffer") || is(c, "glDrawBuffer") || is(c, "glReadBuffer") || is(c, "glDeleteTextures") ||
          is(c, "glDeleteProgram"))
        continue;
      if (is(c, "glGenTextures")) {
        for (long long t : c.args[1].ints) {
          textures.insert(t);
          maxTexture = std::max(maxTexture, t);
          init.push_back("  glGenTextures(1, &texture[" + std::to_string(t) + "]);");
        }
        continue;
      }
      if (is(c, "glBindTexture")) {
        long long t = c.args[1].i;
        if (t != 0 && !textures.count(t))
          throw Error("this state draws a texture the demo rendered itself for this frame (a live view), which no "
                      "recorded call makes: export another view");
        if (t) c.args[1] = code("texture[" + std::to_string(t) + "]");
        lastBind = text(c);
        bindInInit = false;
        display.push_back(lastBind);
        continue;
      }
      if (is(c, "glPixelStorei")) {
        init.push_back(text(c));
        display.push_back(text(c));
        continue;
      }
      if (is(c, "glTexImage2D") || is(c, "glTexImage3D")) {
        if (!bindInInit) init.push_back(lastBind), bindInInit = true;
        gl::Arg& px = c.args[is(c, "glTexImage3D") ? 9 : 8];
        if (px.bytes && !px.bytes->empty()) {
          std::string at = "texels(" + std::to_string(texels.size()) + ", " + std::to_string(px.bytes->size()) + ")";
          texels.insert(texels.end(), px.bytes->begin(), px.bytes->end());
          px = code(at);
        } else {
          px = code("NULL");
        }
        init.push_back(text(c));
        continue;
      }
      // Shaders and programs: made once, in init(); object[k] as numbered.
      static const std::map<std::string, int> objectArgs = {{"glShaderSource", 1}, {"glCompileShader", 1},
                                                            {"glLinkProgram", 1},  {"glDeleteShader", 1},
                                                            {"glAttachShader", 2}, {"glBindAttribLocation", 1},
                                                            {"glUseProgram", 1},   {"glGetUniformLocation", 1}};
      auto obj = objectArgs.find(c.name);
      if (obj != objectArgs.end())
        for (int k = 0; k < obj->second; ++k)
          if (c.args[size_t(k)].i) {
            maxObject = std::max(maxObject, c.args[size_t(k)].i);
            c.args[size_t(k)] = code("object[" + std::to_string(c.args[size_t(k)].i) + "]");
          }
      if (is(c, "glCreateShader") || is(c, "glCreateProgram")) {
        maxObject = std::max(maxObject, c.result);
        c.hasResult = false;
        init.push_back("  object[" + std::to_string(c.result) + "] = " + gl::formatCall(c, true));
        continue;
      }
      if (is(c, "glShaderSource") || is(c, "glCompileShader") || is(c, "glLinkProgram") || is(c, "glDeleteShader") ||
          is(c, "glAttachShader") || is(c, "glBindAttribLocation")) {
        init.push_back(text(c));
        continue;
      }
      if (is(c, "glUseProgram")) {
        program = calls[i].args[0].i;
        display.push_back(text(c));
        continue;
      }
      if (is(c, "glGetUniformLocation")) {
        int j = ++locations;
        locationOf[{program, c.result}] = j;
        c.hasResult = false;
        display.push_back("  location[" + std::to_string(j) + "] = " + gl::formatCall(c, true));
        continue;
      }
      if (std::strncmp(c.name, "glUniform", 9) == 0 && !c.args.empty()) {
        auto loc = locationOf.find({program, c.args[0].i});
        if (loc != locationOf.end()) c.args[0] = code("location[" + std::to_string(loc->second) + "]");
      }
      if (is(c, "glViewport")) commentViewport();
      if (is(c, "glEnable") || is(c, "glDisable")) commentBatch(c);
      if (is(c, "glBegin")) {
        size_t end = i + 1;
        while (end < calls.size() && !is(calls[end], "glEnd")) ++end;
        if (end == calls.size()) throw Error("a recorded glBegin has no glEnd", kExitFailure);
        block(std::vector<gl::Call>(calls.begin() + long(i) + 1, calls.begin() + long(end)), c, calls[end]);
        i = end;
        continue;
      }
      display.push_back(text(c));
    }
  }
};
}  // namespace

ExportedProgram exportC(const std::vector<gl::Call>& recorded, const Frame& frame, const ExportInfo& info) {
  Generator g{frame, {}, {}, {}, {}, {}, 0, 0, 0, 0, {}, 0, "", false, 0, -1, 0};
  std::vector<gl::Call> calls = numberObjects(recorded);
  g.run(calls);
  bool accum = false;
  for (const gl::Call& c : calls) accum |= is(c, "glAccum");

  std::string s;
  s += "/* " + commentSafe(info.title) + "\n *\n";
  s += wrap(commentSafe(info.about), " * ");
  s += " *\n * The OpenGL calls below are the ones the suite made to draw this state of the demo, recorded\n"
       " * as they were made:\n *     " +
       commentSafe(info.state) +
       "\n"
       " * so this program draws the same picture (demos/" +
       info.demo +
       "/ holds the demo that made it).\n"
       " *\n * Build and run it in a window (Esc closes it):\n"
       " *     cc -std=c99 -Wall -Werror " +
       info.sourceName +
       " -o fig -lglfw -lGL -lm && ./fig\n"
       " * or offscreen with OSMesa, writing the picture as a binary PPM:\n"
       " *     cc -std=c99 -Wall -Werror -DOFFSCREEN " +
       info.sourceName + " -o fig -lOSMesa -lm && ./fig out.ppm\n";
  if (!g.texels.empty())
    s += " * The texture images are read from " + info.texelsName +
         " (every glTexImage2D's and glTexImage3D's bytes, in call order):\n"
         " * run the program in the folder that holds it.\n";
  // Panels that show a GL render the demo made in its measurement passes
  // (VI.7's sampling modes, the parallax modes) are such images here.
  std::vector<std::string> rendered;
  for (const TextureDesc& t : frame.textures)
    for (const auto& [k, v] : t.params)
      if (k == "made_by") rendered.push_back(t.name), (void)v;
  if (!rendered.empty()) {
    // One name per kind of picture, with how many there are ("jitter_render
    // (9 textures)"), not the same name nine times.
    std::map<std::string, int> count;
    std::vector<std::string> order;
    for (const std::string& n : rendered)
      if (count[n]++ == 0) order.push_back(n);
    std::string names;
    for (const std::string& n : order)
      names += (names.empty() ? "" : ", ") + n + (count[n] > 1 ? " (" + std::to_string(count[n]) + " textures)" : "");
    s += " *\n" +
         wrap(commentSafe("Some panels show pictures the demo rendered in earlier passes of its own (its measurement, "
                          "with shaders or the accumulation buffer): " +
                          names +
                          ". This program draws those "
                          "pictures as textures; the passes that made them are in demos/" +
                          info.demo + "/."),
              " * ");
  }
  s += " * Change a call, build again, and see what it does.\n */\n";
  s += "#define GL_GLEXT_PROTOTYPES 1\n#include <stdio.h>\n#include <stdlib.h>\n"
       "#ifdef OFFSCREEN\n#include <GL/osmesa.h>\n#else\n#include <GLFW/glfw3.h>\n#endif\n"
       "#include <GL/gl.h>\n#include <GL/glext.h>\n\n";
  s += "enum { WIDTH = " + std::to_string(info.width) + ", HEIGHT = " + std::to_string(info.height) + " };\n";
  if (g.maxTexture)
    s += "static GLuint texture[" + std::to_string(g.maxTexture + 1) + "]; /* texture[k]: the k-th texture made */\n";
  if (g.maxObject)
    s += "static GLuint object[" + std::to_string(g.maxObject + 1) +
         "];  /* shaders and programs, in the order made */\n";
  if (g.locations) s += "static GLint location[" + std::to_string(g.locations + 1) + "];  /* uniform locations */\n";
  if (!g.texels.empty()) {
    s += "\n/* The texture images: " + std::to_string(g.texels.size()) + " bytes from " + info.texelsName +
         ". */\n"
         "static unsigned char *texel_file;\n\n"
         "static void load_texels(void) {\n"
         "  FILE *f = fopen(\"" +
         info.texelsName +
         "\", \"rb\");\n"
         "  long want = " +
         std::to_string(g.texels.size()) +
         "L;\n"
         "  texel_file = malloc((size_t)want);\n"
         "  if (!f || !texel_file || fread(texel_file, 1, (size_t)want, f) != (size_t)want) {\n"
         "    fprintf(stderr, \"cannot read %ld bytes of " +
         info.texelsName +
         " (run this program in its folder)\\n\", want);\n"
         "    exit(2);\n  }\n  fclose(f);\n}\n\n"
         "static const void *texels(long offset, long bytes) {\n  (void)bytes;\n  return texel_file + offset;\n}\n";
  }
  s += "\n";
  for (const std::string& a : g.arrays) s += a + "\n\n";
  s += "/* Textures and programs, made once. */\nstatic void init(void) {\n";
  for (const std::string& l : g.init) s += l + "\n";
  s += "}\n\n/* The picture: the calls of every frame. */\nstatic void display(void) {\n";
  for (const std::string& l : g.display) s += l + "\n";
  s += "}\n\n";
  std::string accumBits = accum ? "16" : "0";
  s += "#ifdef OFFSCREEN\n"
       "int main(int argc, char **argv) {\n"
       "  if (argc != 2) {\n    fprintf(stderr, \"usage: %s OUT.ppm\\n\", argv[0]);\n    return 2;\n  }\n"
       "  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,\n"
       "                         OSMESA_ACCUM_BITS, " +
       accumBits +
       ", OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};\n"
       "  OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, NULL);\n"
       "  unsigned char *rgba = malloc((size_t)WIDTH * HEIGHT * 4);\n"
       "  if (!ctx || !rgba || !OSMesaMakeCurrent(ctx, rgba, GL_UNSIGNED_BYTE, WIDTH, HEIGHT)) {\n"
       "    fprintf(stderr, \"no OSMesa context\\n\");\n    return 1;\n  }\n" +
       std::string(g.texels.empty() ? "" : "  load_texels();\n") +
       "  init();\n  display();\n  glFinish();\n"
       "  FILE *out = fopen(argv[1], \"wb\");\n"
       "  if (!out) {\n    fprintf(stderr, \"cannot write %s\\n\", argv[1]);\n    return 2;\n  }\n"
       "  fprintf(out, \"P6\\n%d %d\\n255\\n\", WIDTH, HEIGHT);\n"
       "  for (int y = HEIGHT - 1; y >= 0; --y) /* OSMesa's row 0 is the bottom */\n"
       "    for (int x = 0; x < WIDTH; ++x) fwrite(rgba + ((size_t)y * WIDTH + x) * 4, 1, 3, out);\n"
       "  fclose(out);\n  OSMesaDestroyContext(ctx);\n  return 0;\n}\n"
       "#else\n"
       "static void key(GLFWwindow *w, int k, int scancode, int action, int mods) {\n"
       "  (void)scancode, (void)mods;\n"
       "  if (k == GLFW_KEY_ESCAPE && action == GLFW_PRESS) glfwSetWindowShouldClose(w, GLFW_TRUE);\n}\n\n"
       "int main(void) {\n"
       "  if (!glfwInit()) return 1;\n"
       "  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2); /* 2.1, no profile: compatibility, fixed function */\n"
       "  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);\n"
       "  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);  /* the picture has one size */\n"
       "  glfwWindowHint(GLFW_DEPTH_BITS, 24);\n  glfwWindowHint(GLFW_STENCIL_BITS, 8);\n";
  if (accum)
    s += "  glfwWindowHint(GLFW_ACCUM_RED_BITS, 16);\n  glfwWindowHint(GLFW_ACCUM_GREEN_BITS, 16);\n"
         "  glfwWindowHint(GLFW_ACCUM_BLUE_BITS, 16);\n  glfwWindowHint(GLFW_ACCUM_ALPHA_BITS, 16);\n";
  s += "  GLFWwindow *win = glfwCreateWindow(WIDTH, HEIGHT, \"" + commentSafe(info.demo) +
       "\", NULL, NULL);\n"
       "  if (!win) {\n    glfwTerminate();\n    return 1;\n  }\n"
       "  glfwMakeContextCurrent(win);\n  glfwSetKeyCallback(win, key);\n" +
       std::string(g.texels.empty() ? "" : "  load_texels();\n") +
       "  init();\n"
       "  while (!glfwWindowShouldClose(win)) {\n    display();\n    glfwSwapBuffers(win);\n"
       "    glfwWaitEvents(); /* nothing moves: draw again only when something happens */\n  }\n"
       "  glfwTerminate();\n  return 0;\n}\n#endif\n";
  return {s, std::move(g.texels)};
}

static std::string texelsPath(const std::string& path) {
  bool dotC = path.size() > 2 && path.compare(path.size() - 2, 2, ".c") == 0;
  return (dotC ? path.substr(0, path.size() - 2) : path) + ".texels";
}

void nameExport(const std::string& path, ExportInfo* info) {
  auto base = [](const std::string& p) {
    size_t slash = p.find_last_of('/');
    return slash == std::string::npos ? p : p.substr(slash + 1);
  };
  info->sourceName = base(path);
  info->texelsName = base(texelsPath(path));
}

void checkExportWritable(const std::string& path) {
  checkWritable(path);
  checkWritable(texelsPath(path));
}

void writeExport(const std::string& path, const ExportedProgram& p) {
  if (!p.texels.empty()) writeFileAtomic(texelsPath(path), std::string(p.texels.begin(), p.texels.end()));
  writeFileAtomic(path, p.source);
}
}  // namespace ts
