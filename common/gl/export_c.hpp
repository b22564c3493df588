// common/gl/export_c.hpp — a state of a demo as a standalone C99 program
// (--export-c FILE.c), made from the GL calls recorded while the suite drew
// that state's picture, so the program makes the same calls.
//
// The program opens a GLFW window, or, built with -DOFFSCREEN, renders with
// OSMesa and writes the picture as a binary PPM:
//   cc -std=c99 -Wall -Werror FILE.c -o fig -lglfw -lGL -lm && ./fig
//   cc -std=c99 -Wall -Werror -DOFFSCREEN FILE.c -o fig -lOSMesa -lm && ./fig out.ppm
// Texture images go into a file beside it (FILE.texels: the bytes of every
// glTexImage2D, in call order), which the program reads at start.
#pragma once
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/gl/gl_record.hpp"

namespace ts {
struct ExportInfo {
  std::string demo, title, about;  // the figure's claim goes into the header comment
  std::string state;               // "build/bin/quad_distortion --size 1024x512 --filter=nearest ..."
  std::string sourceName;          // "fig.c": named in the build lines
  std::string texelsName;          // "fig.texels": the file the program reads (its own folder)
  int width = 0, height = 0;
};

struct ExportedProgram {
  std::string source;
  std::vector<unsigned char> texels;  // written as info.texelsName
};

// Throws ts::Error (exit status 2, one line) when the picture cannot be
// exported: it draws a texture the scene rendered itself this frame (a live
// view), so no recorded call makes its contents.
ExportedProgram exportC(const std::vector<gl::Call>& recorded, const Frame& frame, const ExportInfo& info);

// The names a program written to `path` uses: FILE.c and FILE.texels
// beside it (FILE without its ".c").
void nameExport(const std::string& path, ExportInfo* info);
// Throws ts::Error (exit 2, one line) when FILE.c or FILE.texels beside it
// cannot be written: said before anything renders or any file is written.
void checkExportWritable(const std::string& path);
// Writes the program to `path` and its texels beside it (atomically).
void writeExport(const std::string& path, const ExportedProgram& program);
}  // namespace ts
