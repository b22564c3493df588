#include "common/gl/gl_listing.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <unordered_map>

#include "common/gl/render.hpp"

namespace ts {
std::vector<gl::Call> recordPicture(Renderer& r, const Frame& frame) {
  // Cached textures and programs are dropped first, so the record holds how
  // each was made, not only its binds (and no deletions of the old ones).
  r.release();
  gl::Recording rec;
  r.draw(frame, true);
  return rec.take();
}

gl::CallList recordRender(Renderer& r, const std::function<void()>& draw) {
  r.release();
  gl::Recording rec;
  draw();
  // Kept as long as the figure (a picture's listing): without the vector's
  // spare room, up to half its calls' size again.
  std::vector<gl::Call> calls = rec.take();
  calls.shrink_to_fit();
  return std::make_shared<const std::vector<gl::Call>>(std::move(calls));
}

std::vector<CallSection> pictureSections(const Frame& frame, std::vector<gl::Call> frameCalls) {
  std::vector<CallSection> out;
  for (size_t t = 0; t < frame.textures.size(); ++t) {
    const TextureDesc& d = frame.textures[t];
    if (!d.renderedBy) continue;
    std::string panels;
    for (const Panel& p : frame.panels)
      for (const Batch& b : p.batches)
        if (b.texture == int(t) && panels.find("'" + p.id + "'") == std::string::npos)
          panels += (panels.empty() ? "'" : ", '") + p.id + "'";
    std::string size = d.image ? std::to_string(d.image->width) + "x" + std::to_string(d.image->height) : "";
    out.push_back({"the picture in " + (panels.empty() ? std::string("no panel") : "panel " + panels) +
                       (size.empty() ? "" : " (a " + size + " texture)") + " was rendered by:",
                   d.renderedBy});
  }
  std::string heading = out.empty() ? ""
                                    : "the frame, drawn with those pictures as textures (object names numbered anew):";
  out.push_back({heading, std::make_shared<const std::vector<gl::Call>>(std::move(frameCalls))});
  return out;
}

namespace {
bool is(const gl::Call& c, const char* name) { return std::strcmp(c.name, name) == 0; }

// Which arguments of a call name a texture ('t'), a program/shader ('p'), a
// framebuffer ('f') or a renderbuffer ('r').
const char* nameRoles(const gl::Call& c) {
  static const std::map<std::string, const char*> roles = {{"glBindTexture", " t"},
                                                           {"glDeleteTextures", " t"},
                                                           {"glGenTextures", " t"},
                                                           {"glFramebufferTexture2D", "   t"},
                                                           {"glGenFramebuffers", " f"},
                                                           {"glBindFramebuffer", " f"},
                                                           {"glDeleteFramebuffers", " f"},
                                                           {"glGenRenderbuffers", " r"},
                                                           {"glBindRenderbuffer", " r"},
                                                           {"glDeleteRenderbuffers", " r"},
                                                           {"glFramebufferRenderbuffer", "   r"},
                                                           {"glUseProgram", "p"},
                                                           {"glAttachShader", "pp"},
                                                           {"glShaderSource", "p"},
                                                           {"glCompileShader", "p"},
                                                           {"glLinkProgram", "p"},
                                                           {"glDeleteShader", "p"},
                                                           {"glDeleteProgram", "p"},
                                                           {"glGetUniformLocation", "p"},
                                                           {"glGetAttribLocation", "p"},
                                                           {"glBindAttribLocation", "p"},
                                                           {"glGetProgramiv", "p"},
                                                           {"glGetShaderiv", "p"},
                                                           {"glGetProgramInfoLog", "p"},
                                                           {"glGetShaderInfoLog", "p"}};
  auto it = roles.find(c.name);
  return it == roles.end() ? "" : it->second;
}
}  // namespace

namespace {
// Numbers GL object names call by call, in the order they were made.
class ObjectNumbers {
 public:
  // True when `c` names an object (a copy of it is numbered); most calls of
  // a recording (vertices, colours) do not, and are read as they are.
  static bool names(const gl::Call& c) {
    if (c.hasResult && (is(c, "glCreateProgram") || is(c, "glCreateShader"))) return true;
    const char* roles = nameRoles(c);
    for (size_t k = 0; roles[k] && k < c.args.size(); ++k)
      if (roles[k] != ' ') return true;
    return false;
  }
  void apply(gl::Call& c) {
    // Creation first, so names are numbered in the order they were made.
    if (c.hasResult && (is(c, "glCreateProgram") || is(c, "glCreateShader"))) c.result = number('p', c.result);
    const char* roles = nameRoles(c);
    for (size_t k = 0; roles[k] && k < c.args.size(); ++k) {
      if (roles[k] == ' ') continue;
      gl::Arg& a = c.args[k];
      if (a.kind == gl::Arg::Kind::Ints)
        for (long long& v : a.ints) v = number(roles[k], v);
      else a.i = number(roles[k], a.i);
    }
  }

 private:
  long long number(char role, long long name) {
    if (name == 0) return 0LL;
    auto& m = names_[role];
    auto it = m.find(name);
    if (it != m.end()) return it->second;
    long long n = (long long)(m.size()) + 1;
    m.emplace(name, n);
    return n;
  }
  std::map<char, std::unordered_map<long long, long long>> names_;  // per role letter: GL name -> number
};
}  // namespace

std::vector<gl::Call> numberObjects(const std::vector<gl::Call>& calls) {
  ObjectNumbers numbers;
  std::vector<gl::Call> out = calls;
  for (gl::Call& c : out) numbers.apply(c);
  return out;
}

namespace {
// One entry of a listing before shortening: a heading, or a call whose text
// (may hold several lines: a shader's source) is written when it is first
// read.  A listing shows a few vertices of each glBegin: the rest of a mesh
// drawn call by call (a million calls) is counted, never written.
struct Entry {
  Entry() = default;
  explicit Entry(std::string heading) : text_(std::move(heading)), formatted_(true) {}
  Entry(const gl::Call* call, std::shared_ptr<const gl::Call> numbered) : call_(call), numbered_(std::move(numbered)) {}
  const std::string& text() const {
    if (!formatted_) text_ = gl::formatCall(*call_), formatted_ = true;
    return text_;
  }
  bool is(const char* name) const { return call_ && std::strcmp(call_->name, name) == 0; }
  bool changed = false;
  bool vertex = false;  // a glVertex*: ends one vertex's group of calls
  bool picked = false;  // sets the picked pixel's texture state

 private:
  const gl::Call* call_ = nullptr;            // in its section's CallList (alive while the listing is made)
  std::shared_ptr<const gl::Call> numbered_;  // or its copy with object names numbered (call_ points here)
  mutable std::string text_;
  mutable bool formatted_ = false;
};

// The calls as numberObjects would give them, numbered one at a time: a
// recording of a mesh drawn call by call is a million calls, and a copy of
// all of them would double what the listing holds.
void addEntries(const std::vector<gl::Call>& calls, std::vector<Entry>* out, const std::vector<bool>* picked) {
  ObjectNumbers numbers;
  for (size_t k = 0; k < calls.size(); ++k) {
    const gl::Call* call = &calls[k];
    std::shared_ptr<gl::Call> numbered;
    if (ObjectNumbers::names(*call)) {  // numbered even when left out (a query): names count in order of use
      numbered = std::make_shared<gl::Call>(*call);
      numbers.apply(*numbered);
      call = numbered.get();
    }
    if (call->query) continue;
    Entry e(call, std::move(numbered));
    e.picked = picked && k < picked->size() && (*picked)[k];
    e.vertex = std::strncmp(call->name, "glVertex", 8) == 0 && std::strcmp(call->name, "glVertexPointer") != 0 &&
               std::strncmp(call->name, "glVertexAttrib", 14) != 0;
    out->push_back(std::move(e));
  }
}
std::vector<Entry> entries(const std::vector<CallSection>& sections, const std::vector<bool>* pickedLast = nullptr) {
  std::vector<Entry> out;
  for (size_t k = 0; k < sections.size(); ++k) {
    const CallSection& s = sections[k];
    if (!s.heading.empty()) out.emplace_back("/* " + s.heading + " */");
    if (s.calls) addEntries(*s.calls, &out, k + 1 == sections.size() ? pickedLast : nullptr);
  }
  return out;
}
// Marks the entries of `now` that are not in `before`, aligned as a diff
// would: position by position when the two have the same length (a key
// changed values, not structure), the longest common subsequence when that
// is small enough, else as multisets of texts (many vertices added or
// removed: nearly everything changed anyway).
void markChanged(const std::vector<Entry>& before, std::vector<Entry>* now) {
  size_t n = before.size(), m = now->size();
  if (n == m) {
    for (size_t k = 0; k < m; ++k) (*now)[k].changed = (*now)[k].text() != before[k].text();
    return;
  }
  if (n * m <= size_t(4) << 20) {
    // lcs[i][j]: the longest common subsequence of before[i..] and now[j..].
    std::vector<unsigned short> lcs((n + 1) * (m + 1), 0);
    auto at = [&](size_t i, size_t j) -> unsigned short& { return lcs[i * (m + 1) + j]; };
    for (size_t i = n; i-- > 0;)
      for (size_t j = m; j-- > 0;)
        at(i, j) = before[i].text() == (*now)[j].text() ? (unsigned short)(at(i + 1, j + 1) + 1)
                                                        : std::max(at(i + 1, j), at(i, j + 1));
    for (Entry& e : *now) e.changed = true;
    for (size_t i = 0, j = 0; i < n && j < m;) {
      if (before[i].text() == (*now)[j].text()) {
        (*now)[j].changed = false;
        ++i, ++j;
      } else if (at(i + 1, j) >= at(i, j + 1)) {
        ++i;
      } else {
        ++j;
      }
    }
    return;
  }
  std::unordered_map<std::string, int> count;
  for (const Entry& e : before) ++count[e.text()];
  for (Entry& e : *now) {
    auto it = count.find(e.text());
    e.changed = !(it != count.end() && it->second > 0);
    if (!e.changed) --it->second;
  }
}
}  // namespace

std::vector<ListingLine> listing(const std::vector<gl::Call>& calls, const std::vector<gl::Call>* previous,
                                 int keepVertices) {
  auto section = [](const std::vector<gl::Call>& c) {
    return std::vector<CallSection>{{"", std::make_shared<const std::vector<gl::Call>>(c)}};
  };
  if (!previous) return listing(section(calls), nullptr, keepVertices);
  std::vector<CallSection> before = section(*previous);
  return listing(section(calls), &before, keepVertices);
}

std::vector<ListingLine> listing(const std::vector<CallSection>& sections, const std::vector<CallSection>* previous,
                                 int keepVertices, const std::vector<bool>* picked) {
  std::vector<Entry> now = entries(sections, picked);
  if (previous) markChanged(entries(*previous), &now);
  std::vector<ListingLine> out;
  auto emit = [&](const Entry& e) {
    // One listing line per source line (a shader's source spans many).
    const std::string& text = e.text();
    size_t pos = 0;
    while (true) {
      size_t nl = text.find('\n', pos);
      out.push_back({text.substr(pos, nl == std::string::npos ? std::string::npos : nl - pos), e.changed, e.picked});
      if (nl == std::string::npos) break;
      pos = nl + 1;
    }
  };
  size_t i = 0;
  while (i < now.size()) {
    const Entry& e = now[i];
    emit(e);
    ++i;
    if (!e.is("glBegin")) continue;
    // The vertices up to glEnd, in groups: the attribute calls of a vertex
    // and its glVertex.  Kept: the first `keepVertices` groups and every
    // group with a changed call; the rest become "... N more vertices".
    size_t end = i;
    while (end < now.size() && !now[end].is("glEnd")) ++end;
    int vertex = 0, skipped = 0, keptChanged = 0;
    constexpr int kMaxChanged = 64;
    size_t groupStart = i;
    auto flushSkipped = [&] {
      if (skipped > 0)
        out.push_back(
            {"/* ... " + std::to_string(skipped) + (skipped == 1 ? " more vertex */" : " more vertices */"), false});
      skipped = 0;
    };
    for (size_t k = i; k < end; ++k) {
      if (!now[k].vertex && k + 1 < end) continue;
      bool changed = false;
      for (size_t g = groupStart; g <= k; ++g) changed |= now[g].changed;
      // Changed groups are kept for the highlight, but not a whole new
      // mesh: past kMaxChanged they fold like the rest.
      if (keepVertices < 0 || vertex < keepVertices || (changed && ++keptChanged <= kMaxChanged)) {
        flushSkipped();
        for (size_t g = groupStart; g <= k; ++g) emit(now[g]);
      } else {
        ++skipped;
      }
      ++vertex;
      groupStart = k + 1;
    }
    flushSkipped();
    i = end;  // glEnd is emitted by the loop
  }
  return out;
}

namespace {
bool named(const gl::Call& c, const char* name) { return std::strcmp(c.name, name) == 0; }
bool startsWith(const gl::Call& c, const char* prefix) {
  return std::strncmp(c.name, prefix, std::strlen(prefix)) == 0;
}
bool firstArg(const gl::Call& c, long long value) { return !c.args.empty() && c.args[0].i == value; }
}  // namespace

std::vector<bool> batchTextureCalls(const std::vector<gl::Call>& calls, int ordinal) {
  std::vector<bool> picked(calls.size(), false);
  if (ordinal < 0) return picked;
  size_t begin = calls.size();
  for (size_t k = 0, n = 0; k < calls.size(); ++k)
    if (named(calls[k], "glBegin") && int(n++) == ordinal) {
      begin = k;
      break;
    }
  if (begin == calls.size()) return picked;
  picked[begin] = true;
  // The batch's own state: back from its glBegin to the glEnd before it.
  long long bound = -1;
  bool made = false;
  for (size_t k = begin; k-- > 0 && !named(calls[k], "glEnd");) {
    const gl::Call& c = calls[k];
    const bool texMatrix = named(c, "glLoadMatrixf") && k > 0 && named(calls[k - 1], "glMatrixMode") &&
                           firstArg(calls[k - 1], GL_TEXTURE);
    if (startsWith(c, "glTex") || named(c, "glGenTextures") || named(c, "glPixelStorei") || texMatrix ||
        ((named(c, "glEnable") || named(c, "glDisable")) && firstArg(c, GL_TEXTURE_2D)) ||
        (named(c, "glMatrixMode") && firstArg(c, GL_TEXTURE)) || (named(c, "glUseProgram") && !firstArg(c, 0)) ||
        startsWith(c, "glUniform") || named(c, "glActiveTexture")) {
      picked[k] = true;
      made |= startsWith(c, "glTexImage");
    }
    if (named(c, "glBindTexture") && firstArg(c, GL_TEXTURE_2D)) {
      picked[k] = true;
      if (bound < 0 && c.args.size() > 1) bound = c.args[1].i;
    }
  }
  // A texture made for an earlier batch: where it was made (its first
  // binding followed by its images).
  if (!made && bound > 0)
    for (size_t k = 0; k < begin; ++k) {
      if (!(named(calls[k], "glBindTexture") && calls[k].args.size() > 1 && calls[k].args[1].i == bound)) continue;
      size_t j = k + 1;
      while (j < begin && !named(calls[j], "glBindTexture") && !startsWith(calls[j], "glTexImage")) ++j;
      if (j >= begin || !startsWith(calls[j], "glTexImage")) continue;
      picked[k] = true;
      if (k > 0 && named(calls[k - 1], "glGenTextures")) picked[k - 1] = true;
      for (size_t m = k + 1; m < j; ++m) picked[m] = named(calls[m], "glPixelStorei");
      for (; j < begin && (startsWith(calls[j], "glTexImage") || named(calls[j], "glPixelStorei") ||
                           (named(calls[j], "glTexParameteri") && calls[j].args.size() > 1 &&
                            calls[j].args[1].i == GL_TEXTURE_MAX_LEVEL));
           ++j)
        picked[j] = true;
      break;
    }
  return picked;
}

std::string listingText(const std::vector<ListingLine>& lines, const std::string& header) {
  std::string out = "/* " + header + " */\n";
  for (const ListingLine& l : lines) out += l.text + "\n";
  return out;
}
}  // namespace ts
