#pragma once
// The OSMesa and GL entry points the canvas calls, loaded with dlopen on the first draw. Linking
// libOSMesa instead would load its dependencies (libLLVM among them) into every canopy process,
// frames or not: the dynamic loader's relocation of libLLVM alone was 27·10⁶ instructions per run
// (callgrind, bench/RESULTS.md 2026-12-04). GL 2.0 functions come from OSMesaGetProcAddress,
// which is how OSMesa hands out its GL.
#define GL_GLEXT_PROTOTYPES 1  // declarations only, for decltype: nothing here links them
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

namespace canopy::render::internal {

struct GlApi {
  decltype(&::OSMesaCreateContextExt) OSMesaCreateContextExt;
  decltype(&::OSMesaDestroyContext) OSMesaDestroyContext;
  decltype(&::OSMesaMakeCurrent) OSMesaMakeCurrent;
  decltype(&::OSMesaGetCurrentContext) OSMesaGetCurrentContext;

  decltype(&::glAttachShader) AttachShader;
  decltype(&::glBindAttribLocation) BindAttribLocation;
  decltype(&::glBindBuffer) BindBuffer;
  decltype(&::glBlendFunc) BlendFunc;
  decltype(&::glBlendFuncSeparate) BlendFuncSeparate;
  decltype(&::glBufferData) BufferData;
  decltype(&::glBufferSubData) BufferSubData;
  decltype(&::glClear) Clear;
  decltype(&::glClearColor) ClearColor;
  decltype(&::glCompileShader) CompileShader;
  decltype(&::glCreateProgram) CreateProgram;
  decltype(&::glCreateShader) CreateShader;
  decltype(&::glDeleteShader) DeleteShader;
  decltype(&::glDisable) Disable;
  decltype(&::glDrawArrays) DrawArrays;
  decltype(&::glEnable) Enable;
  decltype(&::glEnableVertexAttribArray) EnableVertexAttribArray;
  decltype(&::glFinish) Finish;
  decltype(&::glGenBuffers) GenBuffers;
  decltype(&::glGetProgramiv) GetProgramiv;
  decltype(&::glGetShaderInfoLog) GetShaderInfoLog;
  decltype(&::glGetShaderiv) GetShaderiv;
  decltype(&::glGetUniformLocation) GetUniformLocation;
  decltype(&::glLinkProgram) LinkProgram;
  decltype(&::glShaderSource) ShaderSource;
  decltype(&::glUniform1f) Uniform1f;
  decltype(&::glUniform2f) Uniform2f;
  decltype(&::glUseProgram) UseProgram;
  decltype(&::glVertexAttribPointer) VertexAttribPointer;
  decltype(&::glViewport) Viewport;
};

/// The entry points, loaded once (thread-safe). Throws std::runtime_error naming the library or
/// the function that could not be loaded.
const GlApi& glApi();

}  // namespace canopy::render::internal
