// The OpenGL 4.5 core API as this library calls it: prototypes from
// GL/glcorearb.h, linked against glvnd's libOpenGL, which exports every core
// entry point up to 4.5 and dispatches to the driver of the current context
// (docs/gl.md says why this beats loading pointers with eglGetProcAddress).
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
