// tests/proofread/proofread.cpp — see proofread.hpp.
#include "tests/proofread/proofread.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <set>

#include "common/core/layout.hpp"
#include "common/core/text.hpp"

namespace ts::proofread {
namespace {
using layout::Box;

Label labelOf(const Json& j) {
  Label l;
  l.x = j.at("x").get<float>();
  l.y = j.at("y").get<float>();
  l.text = j.at("text").get<std::string>();
  l.scale = j.at("scale").get<int>();
  const std::string a = j.at("align").get<std::string>();
  l.align = a == "left" ? Align::Left : a == "center" ? Align::Center : Align::Right;
  for (int k = 0; k < 4; ++k) {
    l.color[k] = j.at("color")[size_t(k)].get<float>();
    l.background[k] = j.at("background")[size_t(k)].get<float>();
  }
  return l;
}

Box panelBox(const Json& p) {
  const Json& v = p.at("viewport");
  return {v[0].get<float>(), v[1].get<float>(), v[0].get<float>() + v[2].get<float>(),
          v[1].get<float>() + v[3].get<float>()};
}

std::string str(const Box& b) {
  char s[96];
  std::snprintf(s, sizeof s, "[%g,%g .. %g,%g]", b.x0, b.y0, b.x1, b.y1);
  return s;
}

// A number as a label prints it: its value, how many decimals it shows, and
// where it stands in the text.
struct Token {
  double value;
  int decimals;
  size_t at, length;
};

// The numbers of a text.  A number glued to a letter, underscore or dot
// before it (GL_RGBA8, VI.2, R8) is a name, not a quantity; so is one that
// runs on into a dot and a digit after its decimals (a version, 15.0.6).
std::vector<Token> tokens(const std::string& s) {
  std::vector<Token> out;
  size_t i = 0;
  auto digit = [&](size_t k) { return k < s.size() && std::isdigit(static_cast<unsigned char>(s[k])); };
  auto glued = [&](size_t k) {  // the character before k makes a name of the number
    if (k == 0) return false;
    const unsigned char c = static_cast<unsigned char>(s[k - 1]);
    return std::isalnum(c) || c == '_' || c == '.';
  };
  while (i < s.size()) {
    if (!digit(i)) {
      ++i;
      continue;
    }
    size_t start = i;
    while (digit(i)) ++i;
    int decimals = 0;
    if (i + 1 < s.size() && s[i] == '.' && digit(i + 1)) {
      ++i;
      while (digit(i)) ++i, ++decimals;
    }
    if (i + 1 < s.size() && s[i] == 'e' && (digit(i + 1) || (s[i + 1] == '-' && digit(i + 2)))) {  // 1.7e-16
      i += s[i + 1] == '-' ? 2 : 1;
      while (digit(i)) ++i;
      decimals = 99;  // compared by its relative size below
    }
    const bool version = i + 1 < s.size() && s[i] == '.' && digit(i + 1);
    if (version)
      while (i < s.size() && (digit(i) || s[i] == '.')) ++i;
    if (glued(start) || version) continue;
    // A formula's constant: a coefficient written against its name (59pi),
    // or a number divided by a name or dividing one (theta/360, pi/8): the
    // formula, not a quantity.  A fraction of two numbers (615/4096) is not.
    const auto alpha = [&](size_t k) { return k < s.size() && std::isalpha(static_cast<unsigned char>(s[k])); };
    const bool coefficient = alpha(i) && s[i] != 'x';  // 16x is a quantity, 59pi a coefficient
    const bool overName = start >= 2 && s[start - 1] == '/' && (alpha(start - 2) || s[start - 2] == ')');
    const bool underName = i + 1 < s.size() && s[i] == '/' && (alpha(i + 1) || s[i + 1] == '(');
    if (coefficient || overName || underName) continue;
    const bool negative = start > 0 && s[start - 1] == '-' &&
                          (start == 1 || !std::isalnum(static_cast<unsigned char>(s[start - 2])));
    if (negative) --start;
    out.push_back({std::stod(s.substr(start, i - start)), decimals, start, i - start});
  }
  return out;
}

// Every number the sidecar holds beside the labels: the measurements, the
// state, the size, the textures' parameters.
void numbersIn(const Json& j, std::vector<double>& out) {
  if (j.is_number()) out.push_back(j.get<double>());
  else if (j.is_string())
    for (const Token& t : tokens(j.get<std::string>())) out.push_back(t.value);
  else if (j.is_array() || j.is_object())
    for (const auto& x : j) numbersIn(x, out);
}

bool grey(const Json& colour) {
  const double r = colour[0].get<double>(), g = colour[1].get<double>(), b = colour[2].get<double>();
  return std::max({r, g, b}) - std::min({r, g, b}) < 0.12;
}
bool sameColour(const Json& a, const Json& b) {
  for (size_t k = 0; k < 3; ++k)
    if (std::abs(a[k].get<double>() - b[k].get<double>()) > 0.02) return false;
  return true;
}
std::string colourName(const Json& c) {
  char s[64];
  std::snprintf(s, sizeof s, "(%.2f, %.2f, %.2f)", c[0].get<double>(), c[1].get<double>(), c[2].get<double>());
  return s;
}
// The two text colours every figure uses for what is not a key: captions
// (white) and measured values (amber), layout.hpp's kWhite and kAmber.
bool plainText(const Json& c) {
  const Json white = {layout::kWhite.r, layout::kWhite.g, layout::kWhite.b};
  const Json amber = {layout::kAmber.r, layout::kAmber.g, layout::kAmber.b};
  return grey(c) || sameColour(c, white) || sameColour(c, amber);
}
}  // namespace

std::vector<std::string> textProblems(const Json& d) {
  std::vector<std::string> out;
  const Box image{0, 0, d.at("size")[0].get<float>(), d.at("size")[1].get<float>()};
  std::vector<Box> panels;
  for (const Json& p : d.at("panels")) {
    const Box b = panelBox(p);
    if (b.w() >= image.w() && b.h() >= image.h()) continue;  // a canvas behind the whole figure
    panels.push_back(b);
  }
  std::vector<std::pair<Label, Box>> labels;
  for (const Json& j : d.at("labels")) {
    Label l = labelOf(j);
    if (l.text.empty()) continue;
    labels.push_back({l, layout::labelBox(l)});
  }
  for (size_t i = 0; i < labels.size(); ++i) {
    const auto& [l, b] = labels[i];
    if (!b.inside(image)) out.push_back("label \"" + l.text + "\" " + str(b) + " leaves the image");
    for (const Box& p : panels)
      if (b.overlaps(p) && !b.inside(p))
        out.push_back("label \"" + l.text + "\" " + str(b) + " crosses the edge of the panel " + str(p));
    if (l.text.size() > 3 && l.text.compare(l.text.size() - 3, 3, "...") == 0)
      out.push_back("label \"" + l.text + "\" is a caption cut short");
    for (size_t k = i + 1; k < labels.size(); ++k)
      if (b.overlaps(labels[k].second))
        out.push_back("labels \"" + l.text + "\" and \"" + labels[k].first.text + "\" overlap");
  }
  return out;
}

std::vector<std::string> numberProblems(const Json& d) {
  std::vector<std::string> out;
  std::vector<double> held;
  numbersIn(d.value("measurements", Json::object()), held);
  numbersIn(d.value("state", Json::object()), held);
  numbersIn(d.value("size", Json::array()), held);
  for (const Json& t : d.value("textures", Json::array())) numbersIn(t.value("params", Json::object()), held);
  const Json& measurements = d.value("measurements", Json::object());
  for (const Json& j : d.at("labels")) {
    const std::string text = j.at("text").get<std::string>();
    std::vector<std::pair<size_t, size_t>> accounted;  // [from, to) of the text the label's own numbers cover
    for (const Json& p : j.value("printed", Json::array())) {
      const std::string name = p.at("measurement").get<std::string>(), shown = p.at("text").get<std::string>();
      if (!measurements.contains(name)) {
        out.push_back("label \"" + text + "\" prints the measurement '" + name + "', which the sidecar does not hold");
        continue;
      }
      char s[64];
      std::snprintf(s, sizeof s, p.at("format").get<std::string>().c_str(), measurements.at(name).get<double>());
      if (shown != s)
        out.push_back("label \"" + text + "\" printed '" + shown + "' for " + name +
                      ", whose value in the sidecar reads '" + s + "'");
      const size_t at = text.find(s);
      if (at == std::string::npos) out.push_back("label \"" + text + "\" does not show " + name + " = " + s);
      else accounted.push_back({at, at + std::string(s).size()});
    }
    std::vector<double> given;
    for (const Json& g : j.value("given", Json::array())) given.push_back(g.at("value").get<double>());
    for (const Token& t : tokens(text)) {
      const bool covered = std::any_of(accounted.begin(), accounted.end(),
                                       [&](const auto& r) { return t.at >= r.first && t.at + t.length <= r.second; });
      if (covered) continue;
      if (t.decimals == 0 && std::abs(t.value) <= 16) continue;
      const double half = t.decimals == 99 ? 0.05 * std::abs(t.value) : 0.5 * std::pow(10.0, -t.decimals) * (1 + 1e-9);
      auto matches = [&](double v) {
        return std::abs(v - t.value) <= half || std::abs(-v - t.value) <= half || std::abs(100 * v - t.value) <= half;
      };
      if (std::any_of(given.begin(), given.end(), matches) || std::any_of(held.begin(), held.end(), matches)) continue;
      out.push_back("label \"" + text + "\" prints " + text.substr(t.at, t.length) +
                    ", which is no measurement, parameter or given value of the figure");
    }
  }
  return out;
}

std::vector<std::string> colourProblems(const Json& d) {
  std::vector<std::string> out;
  const Json legend = d.value("legend", Json::array());
  auto named = [&](const Json& c) {
    return std::any_of(legend.begin(), legend.end(), [&](const Json& e) { return sameColour(e.at("color"), c); });
  };
  std::set<std::string> reported;
  auto need = [&](const Json& c, const std::string& what) {
    if (named(c) || !reported.insert(colourName(c)).second) return;
    out.push_back("the colour " + colourName(c) + " of " + what + " carries meaning and no legend names it");
  };
  for (const Json& p : d.at("panels"))
    for (const Json& b : p.value("batches", Json::array())) {
      if (b.value("texture", -1) != -1 || b.value("primitive", "") == "triangles") continue;
      const Json& v = b.value("vertices", Json::array());
      if (v.empty() || grey(v[0].at("color"))) continue;
      need(v[0].at("color"), "the marks '" + b.value("role", "") + "' in panel '" + p.value("id", "") + "'");
    }
  for (const Json& j : d.at("labels")) {
    const std::string text = j.at("text").get<std::string>();
    const bool swatch = text.find_first_not_of(' ') == std::string::npos;
    if (!swatch && !plainText(j.at("color"))) need(j.at("color"), "the text \"" + text + "\"");
  }
  for (const Json& e : legend) {
    const std::string meaning = e.at("meaning").get<std::string>();
    const Json& ls = d.at("labels");
    // Drawn: a label says it (or a line of it, when it wraps) in its colour or beside a swatch of it.
    auto says = [&](const Json& l) {
      const std::string t = l.at("text").get<std::string>();
      return t.find_first_not_of(' ') != std::string::npos && meaning.find(t) != std::string::npos;
    };
    if (std::none_of(ls.begin(), ls.end(), says)) out.push_back("the legend's entry \"" + meaning + "\" is not drawn");
  }
  return out;
}

double smallestCapitals(const Json& d) {
  double smallest = 1e9;
  for (const Json& j : d.at("labels")) {
    const std::string text = j.at("text").get<std::string>();
    if (text.find_first_not_of(' ') == std::string::npos) continue;
    smallest = std::min(smallest, j.value("capital_px", 0.0));
  }
  return smallest;
}

std::vector<std::string> sizeProblems(const Json& d, double minCapitals) {
  std::vector<std::string> out;
  for (const Json& j : d.at("labels")) {
    const std::string text = j.at("text").get<std::string>();
    if (text.find_first_not_of(' ') == std::string::npos) continue;
    const int scale = j.at("scale").get<int>(), recorded = j.value("capital_px", 0);
    char s[200];
    if (recorded != text::capitalHeight(scale))
      std::snprintf(s, sizeof s, "\"%.40s\": capitals recorded as %d px, but the font draws %d px at scale %d",
                    text.c_str(), recorded, text::capitalHeight(scale), scale);
    else if (recorded < minCapitals)
      std::snprintf(s, sizeof s, "\"%.40s\": capitals %d px tall, below %g px", text.c_str(), recorded, minCapitals);
    else continue;
    out.push_back(s);
  }
  return out;
}
}  // namespace ts::proofread
