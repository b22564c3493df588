// The main() of each demo program: CMake compiles this file once per demo
// with TS_DEMO_ID set to the demo's folder name.
#include "common/core/scene.hpp"

int main(int argc, char** argv) { return ts::runDemo(TS_DEMO_ID, argc, argv); }
