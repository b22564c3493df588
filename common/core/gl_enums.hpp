// common/core/gl_enums.hpp — the OpenGL names the plain data uses, without OpenGL.
//
// A Frame (common/core/frame.hpp), its sidecar and the CPU reference (reference/)
// name GL state by the GL's own enum values (GL_LINEAR, GL_REPEAT, ...), but
// they never call GL: they include this header, not the loader (gl.hpp) or
// the GL headers.  The values are the OpenGL specification's, spelled as in
// <GL/gl.h> and <GL/glext.h>, so a file that includes both sees identical
// definitions (a differing one is a compiler diagnostic, "redefined").
#pragma once

typedef unsigned int GLenum;
typedef unsigned int GLuint;

// Blending, depth, shading, hints (FixedState, Frame::perspectiveHint).
#define GL_ZERO 0
#define GL_ONE 1
#define GL_SRC_ALPHA 0x0302
#define GL_ONE_MINUS_SRC_ALPHA 0x0303
// The alpha test and blend factors a batch may set (Batch::alphaFunc, blendSrc/blendDst).
#define GL_NEVER 0x0200
#define GL_EQUAL 0x0202
#define GL_LEQUAL 0x0203
#define GL_GREATER 0x0204
#define GL_NOTEQUAL 0x0205
#define GL_GEQUAL 0x0206
#define GL_ALWAYS 0x0207
#define GL_SRC_COLOR 0x0300
#define GL_ONE_MINUS_SRC_COLOR 0x0301
#define GL_DST_COLOR 0x0306
#define GL_ONE_MINUS_DST_COLOR 0x0307
#define GL_LESS 0x0201
#define GL_SMOOTH 0x1D01
#define GL_DONT_CARE 0x1100
#define GL_FASTEST 0x1101
#define GL_NICEST 0x1102
// Texture filters.
#define GL_NEAREST 0x2600
#define GL_LINEAR 0x2601
#define GL_NEAREST_MIPMAP_NEAREST 0x2700
#define GL_LINEAR_MIPMAP_NEAREST 0x2701
#define GL_NEAREST_MIPMAP_LINEAR 0x2702
#define GL_LINEAR_MIPMAP_LINEAR 0x2703
// Wrap modes.
#define GL_REPEAT 0x2901
#define GL_CLAMP 0x2900
#define GL_CLAMP_TO_EDGE 0x812F
#define GL_CLAMP_TO_BORDER 0x812D
#define GL_MIRRORED_REPEAT 0x8370
// Texture coordinate generation (glTexGen, Batch::texGen) and 3D textures.
#define GL_EYE_LINEAR 0x2400
#define GL_OBJECT_LINEAR 0x2401
#define GL_TEXTURE_3D 0x806F
// The environment-mapping texgen modes and cube-map textures (TexGen, TextureDesc::cube).
#define GL_SPHERE_MAP 0x2402
#define GL_NORMAL_MAP 0x8511
#define GL_REFLECTION_MAP 0x8512
#define GL_TEXTURE_CUBE_MAP 0x8513
// Texture environment modes.
#define GL_REPLACE 0x1E01
#define GL_MODULATE 0x2100
#define GL_DECAL 0x2101
#define GL_BLEND 0x0BE2
#define GL_ADD 0x0104
// GL_COMBINE on a second texture unit (Batch::texture1, ts::Combine).
#define GL_TEXTURE 0x1702
#define GL_COMBINE 0x8570
#define GL_ADD_SIGNED 0x8574
#define GL_INTERPOLATE 0x8575
#define GL_CONSTANT 0x8576
#define GL_PRIMARY_COLOR 0x8577
#define GL_PREVIOUS 0x8578
#define GL_SUBTRACT 0x84E7
#define GL_MODULATE_ADD_ATI 0x8744
