#include "common/core/options.hpp"

#include <array>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "common/core/error.hpp"
#include "common/core/image.hpp"

namespace ts {
void Options::addBool(const std::string& name, bool* v, const std::string& help, char key) {
  items_.push_back({Item::Bool, name, help, v, {}, 0, 1, 1, key, 0, {}});
}
void Options::addEnum(const std::string& name, int* v, std::vector<std::string> choices, const std::string& help,
                      char key) {
  items_.push_back({Item::Enum, name, help, v, std::move(choices), 0, 0, 1, key, 0, {}});
}
void Options::addInt(const std::string& name, int* v, int lo, int hi, const std::string& help, char up, char down,
                     int step) {
  items_.push_back({Item::Int, name, help, v, {}, double(lo), double(hi), double(step), up, down, {}});
}
void Options::addFloat(const std::string& name, float* v, float lo, float hi, const std::string& help, char up,
                       char down, float step) {
  items_.push_back({Item::Float, name, help, v, {}, lo, hi, step, up, down, {}});
}
void Options::addText(const std::string& name, std::string* v, const std::string& help,
                      std::function<void(const std::string&)> validate) {
  items_.push_back({Item::Text, name, help, v, {}, 0, 0, 1, 0, 0, std::move(validate)});
}

void Options::addFile(const std::string& name, std::string* v, const std::string& help,
                      std::function<void(const std::string&)> validate) {
  addText(name, v, help, std::move(validate));
  items_.back().metavar = "FILE";
}

Options::Item* Options::find(const std::string& name) {
  for (auto& it : items_)
    if (it.name == name) return &it;
  return nullptr;
}
bool Options::has(const std::string& name) const {
  return std::any_of(items_.begin(), items_.end(), [&](const Item& i) { return i.name == name; });
}

static double parseNumber(const std::string& name, const std::string& s) {
  errno = 0;
  char* end = nullptr;
  double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || errno != 0 || !std::isfinite(v))
    throw Error("--" + name + ": '" + s + "' is not a number");
  return v;
}

static std::string formatNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

void Options::set(const std::string& name, const std::string& value) {
  Item* it = find(name);
  if (!it) throw Error("unknown option --" + name + " (see --help)");
  switch (it->kind) {
    case Item::Bool: {
      bool* b = static_cast<bool*>(it->target);
      if (value == "on" || value == "true" || value == "1" || value == "yes") *b = true;
      else if (value == "off" || value == "false" || value == "0" || value == "no") *b = false;
      else throw Error("--" + name + ": expected on or off, got '" + value + "'");
      break;
    }
    case Item::Enum: {
      auto pos = std::find(it->choices.begin(), it->choices.end(), value);
      if (pos == it->choices.end()) {
        std::string all;
        for (const auto& c : it->choices) all += (all.empty() ? "" : ", ") + c;
        throw Error("--" + name + ": '" + value + "' is not one of " + all);
      }
      *static_cast<int*>(it->target) = int(pos - it->choices.begin());
      break;
    }
    case Item::Int: {
      double v = parseNumber(name, value);
      if (v != std::floor(v) || v < it->lo || v > it->hi)
        throw Error("--" + name + ": " + value + " is not an integer in [" + formatNumber(it->lo) + ", " +
                    formatNumber(it->hi) + "]");
      *static_cast<int*>(it->target) = int(v);
      break;
    }
    case Item::Float: {
      double v = parseNumber(name, value);
      if (v < it->lo || v > it->hi)
        throw Error("--" + name + ": " + value + " is outside [" + formatNumber(it->lo) + ", " + formatNumber(it->hi) +
                    "]");
      *static_cast<float*>(it->target) = float(v);
      break;
    }
    case Item::Text:
      if (it->validate) it->validate(value);
      *static_cast<std::string*>(it->target) = value;
      break;
  }
}

void Options::parse(const std::vector<std::string>& args) {
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("--", 0) != 0 || a.size() == 2) throw Error("unexpected argument '" + a + "' (see --help)");
    std::string body = a.substr(2), value;
    size_t eq = body.find('=');
    bool hasValue = eq != std::string::npos;
    if (hasValue) {
      value = body.substr(eq + 1);
      body = body.substr(0, eq);
    }
    Item* it = find(body);
    if (!it && !hasValue && body.rfind("no-", 0) == 0) {
      Item* neg = find(body.substr(3));
      if (neg && neg->kind == Item::Bool) {
        *static_cast<bool*>(neg->target) = false;
        continue;
      }
    }
    if (!it) throw Error("unknown option --" + body + " (see --help)");
    if (!hasValue) {
      if (it->kind == Item::Bool) {
        *static_cast<bool*>(it->target) = true;
        continue;
      }
      if (i + 1 >= args.size()) throw Error("--" + body + " needs a value (see --help)");
      value = args[++i];
    }
    set(body, value);
  }
}

bool Options::handleKey(char key) {
  if (key == 0) return false;
  for (auto& it : items_) {
    bool up = it.key == key, down = it.keyDown == key;
    if (!up && !down) continue;
    switch (it.kind) {
      case Item::Bool: *static_cast<bool*>(it.target) ^= true; break;
      case Item::Enum: {
        int* v = static_cast<int*>(it.target);
        *v = (*v + 1) % int(it.choices.size());
        break;
      }
      case Item::Int: {
        int* v = static_cast<int*>(it.target);
        *v = std::clamp(*v + (up ? 1 : -1) * int(it.step), int(it.lo), int(it.hi));
        break;
      }
      case Item::Float: {
        float* v = static_cast<float*>(it.target);
        *v = std::clamp(*v + float((up ? 1 : -1) * it.step), float(it.lo), float(it.hi));
        break;
      }
      case Item::Text: break;
    }
    return true;
  }
  return false;
}

void Options::resetToDefaults() {
  // Text options left empty are not in stateFlags(): empty them first.
  for (auto& it : items_)
    if (it.kind == Item::Text) static_cast<std::string*>(it.target)->clear();
  parse(defaults_);
}

char Options::keyOf(const std::vector<std::string>& names, bool up) const {
  for (const std::string& n : names)
    for (const auto& it : items_)
      if (it.name == n && (up ? it.key : it.keyDown)) return up ? it.key : it.keyDown;
  return 0;
}

bool Options::adjust(const std::string& name, const std::function<double(double)>& f) {
  Item* it = find(name);
  if (!it || (it->kind != Item::Int && it->kind != Item::Float)) return false;
  if (it->kind == Item::Int) {
    int* v = static_cast<int*>(it->target);
    double want = f(double(*v));
    if (!std::isfinite(want)) return false;
    int next = int(std::lround(std::clamp(want, it->lo, it->hi)));
    if (next == *v) return false;
    *v = next;
    return true;
  }
  float* v = static_cast<float*>(it->target);
  double want = f(double(*v));
  if (!std::isfinite(want)) return false;
  float next = float(std::clamp(want, it->lo, it->hi));
  if (next == *v) return false;
  *v = next;
  return true;
}

std::string Options::valueOf(const Item& it) const {
  switch (it.kind) {
    case Item::Bool: return *static_cast<bool*>(it.target) ? "on" : "off";
    case Item::Enum: return it.choices[size_t(*static_cast<int*>(it.target))];
    case Item::Int: return std::to_string(*static_cast<int*>(it.target));
    case Item::Float: return formatNumber(*static_cast<float*>(it.target));
    case Item::Text: return *static_cast<std::string*>(it.target);
  }
  return "";
}

static std::string keyName(char k) {
  if (k == ' ') return "space";
  return std::string(1, k);
}

std::string Options::helpText() const {
  std::ostringstream o;
  for (const auto& it : items_) {
    std::string flag = "--" + it.name;
    switch (it.kind) {
      case Item::Bool: flag += "[=on|off]"; break;
      case Item::Enum: {
        std::string all;
        for (const auto& c : it.choices) all += (all.empty() ? "" : "|") + c;
        flag += " " + all;
        break;
      }
      case Item::Int:
      case Item::Float: flag += " [" + formatNumber(it.lo) + ".." + formatNumber(it.hi) + "]"; break;
      case Item::Text: flag += " " + it.metavar; break;
    }
    std::string keys;
    if (it.key) keys = "key " + keyName(it.key);
    if (it.keyDown) keys += "/" + keyName(it.keyDown);
    char line[512];
    std::snprintf(line, sizeof line, "  %-34s %-10s %s (now %s)\n", flag.c_str(), keys.c_str(), it.help.c_str(),
                  valueOf(it).c_str());
    o << line;
  }
  return o.str();
}

std::string Options::keysText() const {
  std::string out;
  for (const auto& it : items_) {
    if (!it.key) continue;
    if (!out.empty()) out += "  ";
    out += keyName(it.key);
    if (it.keyDown) out += "/" + keyName(it.keyDown);
    out += ": " + it.name;
  }
  return out;
}

std::string Options::stateText() const {
  std::string out;
  for (const auto& it : items_) out += (out.empty() ? "" : " ") + it.name + "=" + valueOf(it);
  return out;
}

std::vector<std::string> Options::stateFlags() const {
  // "--name=value" throughout: unambiguous for bools too, and parse() takes
  // it back.  Empty text (an unset file name) is left out.
  std::vector<std::string> out;
  for (const auto& it : items_) {
    std::string v = valueOf(it);
    if (it.kind == Item::Text && v.empty()) continue;
    out.push_back("--" + it.name + "=" + v);
  }
  return out;
}

std::vector<std::pair<std::string, std::string>> Options::state() const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& it : items_) out.emplace_back(it.name, valueOf(it));
  return out;
}

void parseSize(const std::string& text, int* w, int* h) {
  size_t x = text.find('x');
  auto bad = [&] {
    return Error("--size: '" + text + "' is not WxH with 1 <= W, H <= " + std::to_string(kMaxImageDimension));
  };
  if (x == std::string::npos || x == 0 || x + 1 >= text.size()) throw bad();
  std::string a = text.substr(0, x), b = text.substr(x + 1);
  for (const std::string* s : {&a, &b})
    if (s->size() > 6 || s->find_first_not_of("0123456789") != std::string::npos) throw bad();
  int W = std::atoi(a.c_str()), H = std::atoi(b.c_str());
  if (W < 1 || H < 1 || W > kMaxImageDimension || H > kMaxImageDimension) throw bad();
  *w = W;
  *h = H;
}

std::array<int, 2> parsePixel(const std::string& text, const char* flag) {
  // "X,Y": two non-negative integers of at most 5 digits (sizes stop at 16384).
  const size_t comma = text.find(',');
  auto number = [&](const std::string& v) {
    if (v.empty() || v.size() > 5 || v.find_first_not_of("0123456789") != std::string::npos)
      throw Error(std::string(flag) + ": '" + text + "' is not a pixel X,Y (two whole numbers, 0 = left, top)");
    return std::atoi(v.c_str());
  };
  if (comma == std::string::npos) number("");
  return {number(text.substr(0, comma)), number(text.substr(comma + 1))};
}

std::vector<std::string> parseCommonFlags(int argc, char** argv, CommonFlags* f) {
  std::vector<std::string> rest;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i], name = a, value;
    size_t eq = a.find('=');
    bool inl = a.rfind("--", 0) == 0 && eq != std::string::npos;
    if (inl) {
      name = a.substr(0, eq);
      value = a.substr(eq + 1);
    }
    auto need = [&]() -> std::string {
      if (inl) return value;
      if (i + 1 >= argc) throw Error(name + " needs a value (see --help)");
      return argv[++i];
    };
    auto noValue = [&] {
      if (inl) throw Error(name + " takes no value");
    };
    if (name == "--help" || name == "-h") noValue(), f->help = true;
    else if (name == "--png") f->png = need();
    else if (name == "--json") f->json = need();
    else if (name == "--gl-listing") f->glListing = need();
    else if (name == "--export-c") f->exportC = need();
    else if (name == "--size") parseSize(need(), &f->width, &f->height);
    else if (name == "--backend") f->backend = need();
    else if (name == "--screenshot") f->screenshot = need();
    else if (name == "--keys") f->keys = need();
    else if (name == "--quiet") noValue(), f->quiet = true;
    else if (name == "--inspect") f->inspect.push_back(parsePixel(need(), "--inspect"));
    else if (name == "--footprints") noValue(), f->footprints = true;
    else if (name == "--frames") {
      std::string v = need();
      if (v.empty() || v.size() > 7 || v.find_first_not_of("0123456789") != std::string::npos ||
          std::atoi(v.c_str()) < 1)
        throw Error("--frames: '" + v + "' is not a positive integer");
      f->frames = std::atoi(v.c_str());
    } else {
      rest.push_back(a);
    }
  }
  for (const std::string* p : {&f->png, &f->json, &f->screenshot, &f->glListing, &f->exportC})
    if (!p->empty() && p->back() == '/') throw Error("'" + *p + "' names a directory, not a file");
  // PNG bytes under another image's name would mislead every viewer.
  for (const std::string* p : {&f->png, &f->screenshot}) {
    size_t dot = p->find_last_of('.'), slash = p->find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) continue;
    std::string ext = p->substr(dot);
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".png")
      throw Error("'" + *p + "' ends in " + p->substr(dot) +
                  ", but --png and --screenshot write PNG files: name it .png");
  }
  return rest;
}

std::vector<std::string> sceneFlags(const std::vector<std::string>& flags, CommonFlags* common) {
  std::vector<const char*> argv{"figure"};
  for (const std::string& a : flags) argv.push_back(a.c_str());
  CommonFlags ignored;
  return parseCommonFlags(int(argv.size()), const_cast<char**>(argv.data()), common ? common : &ignored);
}

std::string commonFlagsHelp() {
  return "  --help                             this text\n"
         "  --png FILE                         render offscreen into FILE (no window) and print the measurement\n"
         "  --json FILE                        with --png: also write the sidecar (every parameter of the image)\n"
         "  --gl-listing FILE                  write the OpenGL calls "
         "that draw the state's picture (offscreen, no window)\n"
         "  --export-c FILE.c                  write a standalone C99 program making those calls (and FILE.texels)\n"
         "  --size WxH                         image or window size, 1..16384 each\n"
         "  --backend NAME                     osmesa, egl, hidden (a hidden window), window or auto: a window,\n"
         "                                     or with --png OSMesa, then EGL, then a hidden window\n"
         "  --frames N                         window: close after N frames once measured (tests)\n"
         "  --screenshot FILE                  window: save the last frame to FILE (before the overlay)\n"
         "  --keys STRING                      window: press these keys, one per frame (tests, demos)\n"
         "  --quiet                            do not print the measurement\n"
         "  --inspect X,Y                      with --png: print what GL did at pixel (X, Y) (0,0 = top left): its\n"
         "                                     (s,t,r,q), derivatives, rho, lambda, levels, the texels read and their\n"
         "                                     weights, the reference colour beside GL's; --json gets an \"inspect\"\n"
         "                                     list.  May be given several times.\n"
         "  --footprints                       with --inspect: the "
         "PNG shows the picture with those pixels ringed and,\n"
         "                                     for each, level 0 of its texture around its footprint (preimage,\n"
         "                                     derivatives, EWA ellipse, the 2^lambda square, the texels read)\n";
}
}  // namespace ts
