// exercises/lab1_blit.cpp — seed 002's lab, task 1.
//
// The statement (seed 002, "Zadania do wykonania"): "Napisać procedurę
// mapującą obrazek o rozmiarach 256x256 na prostokątny obszar ekranu o
// dowolnych rozmiarach" — write a procedure that maps a 256×256 image onto
// a rectangle of the screen of any size.
//
// Write: the width x height image that shows `texture` stretched over it,
// each pixel taking the one texel nearest its centre (nearest neighbour, as
// GL_NEAREST does).  Pixel (x, y), x = 0 at the left, y = 0 at the top,
// covers [x, x + 1] x [y, y + 1]; texel (i, j) covers the same in the
// texture's units; texture.at(i, j) reads it (0,0 = top left).
//
// Checked against GL: a screen-aligned quad with the texture, GL_NEAREST,
// at 300×200, 512×512 and 200×300: 0 pixels may differ.  And the counts
// that follow: across 300 pixels, 44 of the 256 texel columns take 2 pixels
// (212 take 1); across 200, 56 are never shown.
#include "exercise.hpp"

ts::Image exercise::blit(const ts::Image& texture, int width, int height) {
  (void)texture, (void)width, (void)height;
  TS_EXERCISE_NOT_DONE("lab1_blit");
}
