#include "sidecar.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace ts {
namespace {
std::string num(double v) {
  if (!std::isfinite(v)) return "null";
  if (v == 0) return "0";  // no "-0"
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}
std::string quote(const std::string& s) {
  std::string o = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') o += '\\', o += char(c);
    else if (c == '\n') o += "\\n";
    else if (c < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", c);
      o += b;
    } else o += char(c);
  }
  return o + "\"";
}
template <int N>
std::string vec(const glm::vec<N, float>& v) {
  std::string o = "[";
  for (int i = 0; i < N; ++i) o += (i ? "," : "") + num(v[i]);
  return o + "]";
}
std::string mat(const glm::mat4& m) {  // column-major, as glLoadMatrixf takes it
  std::string o = "[";
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) o += ((c || r) ? "," : "") + num(m[c][r]);
  return o + "]";
}
const char* primName(Prim p) {
  switch (p) {
    case Prim::Triangles: return "triangles";
    case Prim::Lines: return "lines";
    case Prim::LineStrip: return "line_strip";
    case Prim::LineLoop: return "line_loop";
    case Prim::Points: return "points";
  }
  return "?";
}
}  // namespace

std::string glEnumName(GLenum e) {
  switch (e) {
    case GL_NEAREST: return "GL_NEAREST";
    case GL_LINEAR: return "GL_LINEAR";
    case GL_NEAREST_MIPMAP_NEAREST: return "GL_NEAREST_MIPMAP_NEAREST";
    case GL_LINEAR_MIPMAP_NEAREST: return "GL_LINEAR_MIPMAP_NEAREST";
    case GL_NEAREST_MIPMAP_LINEAR: return "GL_NEAREST_MIPMAP_LINEAR";
    case GL_LINEAR_MIPMAP_LINEAR: return "GL_LINEAR_MIPMAP_LINEAR";
    case GL_REPEAT: return "GL_REPEAT";
    case GL_MIRRORED_REPEAT: return "GL_MIRRORED_REPEAT";
    case GL_CLAMP_TO_EDGE: return "GL_CLAMP_TO_EDGE";
    case GL_CLAMP_TO_BORDER: return "GL_CLAMP_TO_BORDER";
    case GL_REPLACE: return "GL_REPLACE";
    case GL_MODULATE: return "GL_MODULATE";
    case GL_DECAL: return "GL_DECAL";
    case GL_BLEND: return "GL_BLEND";
    case GL_ZERO: return "GL_ZERO";
    case GL_ONE: return "GL_ONE";
    case GL_SRC_ALPHA: return "GL_SRC_ALPHA";
    case GL_ONE_MINUS_SRC_ALPHA: return "GL_ONE_MINUS_SRC_ALPHA";
    case GL_LESS: return "GL_LESS";
    case GL_SMOOTH: return "GL_SMOOTH";
    default: {
      char b[16];
      std::snprintf(b, sizeof b, "0x%04X", e);
      return b;
    }
  }
}

std::string sidecarJson(const Frame& f, const SidecarInfo& info) {
  std::ostringstream o;
  o << "{\n";
  o << "  \"figure\": " << quote(info.figureId) << ",\n";
  o << "  \"book_number\": " << quote(info.bookNumber) << ",\n";
  o << "  \"caption\": " << quote(info.caption) << ",\n";
  o << "  \"demo\": " << quote(info.demo) << ",\n";
  o << "  \"command\": " << quote(info.command) << ",\n";
  o << "  \"state\": {";
  for (size_t i = 0; i < info.state.size(); ++i)
    o << (i ? ", " : "") << quote(info.state[i].first) << ": " << quote(info.state[i].second);
  o << "},\n";
  o << "  \"measurements\": {";
  for (size_t i = 0; i < info.measurements.size(); ++i)
    o << (i ? ", " : "") << quote(info.measurements[i].name) << ": " << num(info.measurements[i].value);
  o << "},\n";
  o << "  \"conventions\": \"matrices column-major as glLoadMatrixf takes them; viewports in pixels from the "
       "top-left of the image; texture row 0 is t = 0; vertex tex is (s,t,r,q)\",\n";
  if (!info.renderer.empty()) o << "  \"renderer\": " << quote(info.renderer) << ",\n";
  o << "  \"size\": [" << f.width << "," << f.height << "],\n";
  o << "  \"fixed_state\": {\"blend_func\": [" << quote(glEnumName(FixedState::blendSrc)) << ", "
    << quote(glEnumName(FixedState::blendDst)) << ", " << quote(glEnumName(FixedState::blendSrcAlpha)) << ", "
    << quote(glEnumName(FixedState::blendDstAlpha)) << "], \"depth_func\": " << quote(glEnumName(FixedState::depthFunc))
    << ", \"shade_model\": " << quote(glEnumName(FixedState::shadeModel))
    << ", \"cull_face\": " << (FixedState::cullFace ? "true" : "false")
    << ", \"lighting\": " << (FixedState::lighting ? "true" : "false") << "},\n";
  o << "  \"clear_color\": " << vec(f.clearColor) << ",\n";
  o << "  \"perspective_correction_hint\": " << quote(f.perspectiveHint == GL_FASTEST ? "GL_FASTEST" : f.perspectiveHint == GL_NICEST ? "GL_NICEST" : "GL_DONT_CARE") << ",\n";
  o << "  \"textures\": [\n";
  for (size_t i = 0; i < f.textures.size(); ++i) {
    const TextureDesc& t = f.textures[i];
    o << "    {\"name\": " << quote(t.name) << ", \"params\": {";
    for (size_t k = 0; k < t.params.size(); ++k)
      o << (k ? ", " : "") << quote(t.params[k].first) << ": " << quote(t.params[k].second);
    o << "}, \"width\": " << (t.image ? t.image->width : 0) << ", \"height\": " << (t.image ? t.image->height : 0)
      << ", \"mipmaps\": " << (t.mipmaps ? (t.mipLevels ? "\"explicit\"" : t.linearLightMips ? "\"box_linear_light\"" : "\"box_2x2\"") : "false")
      << ", \"min_filter\": " << quote(glEnumName(t.minFilter)) << ", \"mag_filter\": " << quote(glEnumName(t.magFilter))
      << ", \"wrap_s\": " << quote(glEnumName(t.wrapS)) << ", \"wrap_t\": " << quote(glEnumName(t.wrapT))
      << ", \"border\": " << vec(t.border) << ", \"max_anisotropy\": " << num(t.maxAnisotropy)
      << ", \"lod_bias\": " << num(t.lodBias) << "}" << (i + 1 < f.textures.size() ? "," : "") << "\n";
  }
  o << "  ],\n";
  o << "  \"programs\": [";
  for (size_t i = 0; i < f.programs.size(); ++i)
    o << (i ? ", " : "") << "{\"name\": " << quote(f.programs[i].first) << ", \"source\": " << quote(f.programs[i].second.file)
      << "}";
  o << "],\n";
  o << "  \"panels\": [\n";
  for (size_t pi = 0; pi < f.panels.size(); ++pi) {
    const Panel& p = f.panels[pi];
    o << "    {\"id\": " << quote(p.id) << ", \"viewport\": [" << p.viewport.x << "," << p.viewport.y << ","
      << p.viewport.w << "," << p.viewport.h << "], \"depth_test\": " << (p.depthTest ? "true" : "false")
      << ", \"clear\": " << (p.clear ? "true" : "false") << ", \"clear_color\": " << vec(p.clearColor)
      << ",\n     \"projection\": " << mat(p.projection) << ",\n     \"modelview\": " << mat(p.modelview)
      << ",\n     \"batches\": [\n";
    for (size_t bi = 0; bi < p.batches.size(); ++bi) {
      const Batch& b = p.batches[bi];
      o << "       {\"role\": " << quote(b.role) << ", \"primitive\": \"" << primName(b.prim)
        << "\", \"texture\": " << b.texture << ", \"tex_env\": " << quote(glEnumName(b.texEnv))
        << ", \"program\": " << quote(b.program) << ", \"uniforms\": {";
      for (size_t u = 0; u < b.uniforms.size(); ++u)
        o << (u ? ", " : "") << quote(b.uniforms[u].name) << ": " << vec(b.uniforms[u].value);
      o << "}, \"line_width\": " << num(b.lineWidth) << ", \"point_size\": " << num(b.pointSize)
        << ", \"blend\": " << (b.blend ? "true" : "false")
        << ",\n        \"vertices\": [";
      for (size_t v = 0; v < b.vertices.size(); ++v) {
        const Vertex& x = b.vertices[v];
        o << (v ? ",\n          " : "\n          ") << "{\"pos\": " << vec(x.pos) << ", \"tex\": " << vec(x.tex)
          << ", \"color\": " << vec(x.color) << "}";
      }
      o << "]}" << (bi + 1 < p.batches.size() ? "," : "") << "\n";
    }
    o << "     ]}" << (pi + 1 < f.panels.size() ? "," : "") << "\n";
  }
  o << "  ],\n";
  o << "  \"labels\": [";
  for (size_t i = 0; i < f.labels.size(); ++i)
    o << (i ? ",\n    " : "\n    ") << "{\"x\": " << num(f.labels[i].x) << ", \"y\": " << num(f.labels[i].y)
      << ", \"text\": " << quote(f.labels[i].text) << ", \"scale\": " << f.labels[i].scale << ", \"align\": \""
      << (f.labels[i].align == Align::Left ? "left" : f.labels[i].align == Align::Center ? "center" : "right")
      << "\", \"color\": " << vec(f.labels[i].color) << ", \"background\": " << vec(f.labels[i].background) << "}";
  o << "]\n}\n";
  return o.str();
}
}  // namespace ts
