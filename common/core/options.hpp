// common/core/options.hpp — one command-line parser for every demo.
//
// A demo binds its state (members of its Scene) to named options.  Each
// option is at once a flag (--diagonal bl-tr), a key in the window (d cycles
// it), a line of --help, and a field of the on-screen state.  So whatever a
// student sees in a window can be rendered to a PNG with the same flags.
#pragma once
#include <array>
#include <functional>
#include <string>
#include <vector>

namespace ts {
class Options {
 public:
  // Bool: --name, --no-name, --name=on|off.  `key` toggles it.
  void addBool(const std::string& name, bool* v, const std::string& help, char key = 0);
  // Enum: --name choice.  `key` cycles through the choices.
  void addEnum(const std::string& name, int* v, std::vector<std::string> choices, const std::string& help,
               char key = 0);
  // Int and float in [lo, hi]; `up`/`down` keys step by `step`.
  void addInt(const std::string& name, int* v, int lo, int hi, const std::string& help, char up = 0, char down = 0,
              int step = 1);
  void addFloat(const std::string& name, float* v, float lo, float hi, const std::string& help, char up = 0,
                char down = 0, float step = 1.0f);
  // Free text checked by `parse` (which throws ts::Error with a reason).
  void addText(const std::string& name, std::string* v, const std::string& help,
               std::function<void(const std::string&)> validate);
  // A file name: the same as addText, shown as "--name FILE" in --help.
  void addFile(const std::string& name, std::string* v, const std::string& help,
               std::function<void(const std::string&)> validate);

  // Applies "--name value" / "--name=value" / "--flag" arguments; throws
  // ts::Error on anything unknown or invalid.
  void parse(const std::vector<std::string>& args);
  void set(const std::string& name, const std::string& value);  // throws
  bool has(const std::string& name) const;
  // Window keys: returns true if `key` changed some option.
  bool handleKey(char key);
  // The demo's own defaults (call before parsing the command line), and the
  // window's Backspace: every option back to them.
  void captureDefaults() { defaults_ = stateFlags(); }
  void resetToDefaults();
  // The key of the first option among `names` (its up key, or its down key):
  // the arrow keys turn and tilt through the demo's own options.  0: none.
  char keyOf(const std::vector<std::string>& names, bool up) const;
  // The mouse: sets the number option `name` to f(its value), clamped to its
  // range.  False when there is no such Int or Float option or nothing changed.
  bool adjust(const std::string& name, const std::function<double(double)>& f);

  std::string helpText() const;   // one line per option, keys included
  std::string keysText() const;   // "d: diagonal  e: edges ..."
  std::string stateText() const;  // "diagonal=tl-br edges=on ..."
  // Flags that reproduce the current state: {"--diagonal=tl-br", ...};
  // parse(stateFlags()) restores it.
  std::vector<std::string> stateFlags() const;
  // (name, value) pairs of the current state, for the sidecar.
  std::vector<std::pair<std::string, std::string>> state() const;

  struct Item {
    enum Kind { Bool, Enum, Int, Float, Text } kind;
    std::string name, help;
    void* target;
    std::vector<std::string> choices;
    double lo = 0, hi = 0, step = 1;
    char key = 0, keyDown = 0;
    std::function<void(const std::string&)> validate;
    std::string metavar = "TEXT";  // Text: what --help shows as its value
  };
  const std::vector<Item>& items() const { return items_; }

 private:
  Item* find(const std::string& name);
  std::string valueOf(const Item& it) const;
  std::vector<Item> items_;
  std::vector<std::string> defaults_;
};

// The flags every program of the suite shares.
struct CommonFlags {
  bool help = false;
  std::string png;            // --png FILE: render offscreen, no window
  std::string json;           // --json FILE: the sidecar of that render
  std::string glListing;      // --gl-listing FILE: the GL calls that draw that render
  std::string exportC;        // --export-c FILE.c: a standalone C program making those calls
  int width = 0, height = 0;  // --size WxH (0 = the demo's default)
  std::string backend = "auto";
  int frames = 0;                           // --frames N: window closes after N frames once measured (tests)
  std::string screenshot;                   // --screenshot FILE: the window's last frame
  std::string keys;                         // --keys STRING: typed into the window, one per frame
  bool quiet = false;                       // --quiet: no measurement printout
  std::vector<std::array<int, 2>> inspect;  // --inspect X,Y (repeatable): the pixels to look inside
  bool footprints = false;  // --footprints: the PNG shows the inspected pixels' footprints on the texture
};

// A figure's flags (FigureSpec::flags) without the common flags among them
// (--inspect X,Y, --footprints: how the figure is drawn, not the scene's
// state), which go to `common` when given.
std::vector<std::string> sceneFlags(const std::vector<std::string>& flags, CommonFlags* common = nullptr);
// Parses "X,Y" (a pixel, 0,0 = top left); throws ts::Error naming `flag`.
std::array<int, 2> parsePixel(const std::string& text, const char* flag);

// Parses "WxH" into w, h; throws ts::Error unless 1 <= w, h <= 16384.
void parseSize(const std::string& text, int* w, int* h);
// Splits argv into the common flags and the rest (demo options).
std::vector<std::string> parseCommonFlags(int argc, char** argv, CommonFlags* out);
std::string commonFlagsHelp();
}  // namespace ts
