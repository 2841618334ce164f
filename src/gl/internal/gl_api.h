// The OpenGL core-profile API, for the GL library's .cpp files only (never a public header).
// The backend's library (libOSMesa or libEGL, and through either LLVM, 100 ms of relocations) is
// loaded only when a context is made, so commands that do not render start fast: every GL entry
// point used is a function pointer here, filled by UseGlFunctionsFrom from the backend's
// OSMesaGetProcAddress or eglGetProcAddress. A call to a GL function not in this list fails to
// compile, which is how the list stays complete.
#pragma once

#include <GL/glcorearb.h>

// X(type, name) for each GL function the renderer calls.
#define URDFSNAP_GL_FUNCTIONS(X)                                      \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                          \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                            \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                                \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                      \
  X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)                    \
  X(PFNGLBINDTEXTUREPROC, glBindTexture)                              \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                      \
  X(PFNGLBLENDFUNCPROC, glBlendFunc)                                  \
  X(PFNGLBLENDFUNCSEPARATEPROC, glBlendFuncSeparate)                  \
  X(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer)                      \
  X(PFNGLBUFFERDATAPROC, glBufferData)                                \
  X(PFNGLBUFFERSTORAGEPROC, glBufferStorage)                          \
  X(PFNGLBUFFERSUBDATAPROC, glBufferSubData)                          \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)        \
  X(PFNGLCLEARPROC, glClear)                                          \
  X(PFNGLCLEARBUFFERFVPROC, glClearBufferfv)                          \
  X(PFNGLCLEARBUFFERUIVPROC, glClearBufferuiv)                        \
  X(PFNGLCLEARCOLORPROC, glClearColor)                                \
  X(PFNGLCLEARDEPTHPROC, glClearDepth)                                \
  X(PFNGLCLIENTWAITSYNCPROC, glClientWaitSync)                        \
  X(PFNGLCOLORMASKPROC, glColorMask)                                  \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                          \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                          \
  X(PFNGLCREATESHADERPROC, glCreateShader)                            \
  X(PFNGLCULLFACEPROC, glCullFace)                                    \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                          \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                          \
  X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)              \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                            \
  X(PFNGLDELETESYNCPROC, glDeleteSync)                                \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                        \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                \
  X(PFNGLDEPTHFUNCPROC, glDepthFunc)                                  \
  X(PFNGLDEPTHMASKPROC, glDepthMask)                                  \
  X(PFNGLDISABLEPROC, glDisable)                                      \
  X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, glDisableVertexAttribArray)    \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                                \
  X(PFNGLDRAWBUFFERSPROC, glDrawBuffers)                              \
  X(PFNGLDRAWELEMENTSPROC, glDrawElements)                            \
  X(PFNGLDRAWELEMENTSINSTANCEDPROC, glDrawElementsInstanced)          \
  X(PFNGLENABLEPROC, glEnable)                                        \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)      \
  X(PFNGLFENCESYNCPROC, glFenceSync)                                  \
  X(PFNGLFINISHPROC, glFinish)                                        \
  X(PFNGLFRAMEBUFFERPARAMETERIPROC, glFramebufferParameteri)          \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer)      \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)            \
  X(PFNGLFRONTFACEPROC, glFrontFace)                                  \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                                \
  X(PFNGLGENERATEMIPMAPPROC, glGenerateMipmap)                        \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                      \
  X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)                    \
  X(PFNGLGENTEXTURESPROC, glGenTextures)                              \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                      \
  X(PFNGLGETACTIVEUNIFORMPROC, glGetActiveUniform)                    \
  X(PFNGLGETERRORPROC, glGetError)                                    \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                              \
  X(PFNGLGETTEXIMAGEPROC, glGetTexImage)                              \
  X(PFNGLGETMULTISAMPLEFVPROC, glGetMultisamplefv)                    \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                  \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                            \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                    \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                              \
  X(PFNGLGETSTRINGPROC, glGetString)                                  \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                \
  X(PFNGLLINEWIDTHPROC, glLineWidth)                                  \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                              \
  X(PFNGLMAPBUFFERRANGEPROC, glMapBufferRange)                        \
  X(PFNGLMULTIDRAWELEMENTSINDIRECTPROC, glMultiDrawElementsIndirect)  \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)                              \
  X(PFNGLPOLYGONOFFSETPROC, glPolygonOffset)                          \
  X(PFNGLREADBUFFERPROC, glReadBuffer)                                \
  X(PFNGLREADPIXELSPROC, glReadPixels)                                \
  X(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage)              \
  X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, glRenderbufferStorageMultisample) \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                            \
  X(PFNGLTEXBUFFERPROC, glTexBuffer)                                  \
  X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                                \
  X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                          \
  X(PFNGLTEXSTORAGE2DPROC, glTexStorage2D)                            \
  X(PFNGLTEXSUBIMAGE2DPROC, glTexSubImage2D)                          \
  X(PFNGLUNIFORM1FPROC, glUniform1f)                                  \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                                  \
  X(PFNGLUNIFORM1UIPROC, glUniform1ui)                                \
  X(PFNGLUNIFORM2FVPROC, glUniform2fv)                                \
  X(PFNGLUNIFORM3FVPROC, glUniform3fv)                                \
  X(PFNGLUNIFORM4FVPROC, glUniform4fv)                                \
  X(PFNGLUNIFORMMATRIX3FVPROC, glUniformMatrix3fv)                    \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)                    \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                                \
  X(PFNGLVERTEXATTRIBDIVISORPROC, glVertexAttribDivisor)              \
  X(PFNGLVERTEXATTRIBIPOINTERPROC, glVertexAttribIPointer)            \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)              \
  X(PFNGLVIEWPORTPROC, glViewport)

namespace urdfsnap::gl {

#define URDFSNAP_DECLARE_GL_FUNCTION(type, name) inline type name = nullptr;
URDFSNAP_GL_FUNCTIONS(URDFSNAP_DECLARE_GL_FUNCTION)
#undef URDFSNAP_DECLARE_GL_FUNCTION

// Fills every pointer above through `get_proc` (OSMesaGetProcAddress or eglGetProcAddress)
// unless they already come from it. Each context's MakeCurrent calls it, so contexts of both
// backends can take turns in one process (the table is process-wide: one backend at a time).
// Returns whether the table changed. Throws urdfsnap::Error naming the first function the
// library does not provide.
using GlProcLookup = void (*(*)(const char* name))();
bool UseGlFunctionsFrom(GlProcLookup get_proc);

}  // namespace urdfsnap::gl
