// The OpenGL core-profile API, for the render library's .cpp files only (never a public header).
// Mesa's libOSMesa exports every GL entry point, so the prototypes are linked directly.
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>
