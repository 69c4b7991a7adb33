#include "render/internal/gl_api.h"

#include <dlfcn.h>

#include <stdexcept>
#include <string>
#include <type_traits>

namespace canopy::render::internal {
namespace {

// libOSMesa's SONAME in Debian 12 (Mesa 22) first; older and unversioned names after.
constexpr const char* kLibraryNames[] = {"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"};

GlApi load() {
  void* library = nullptr;
  for (const char* name : kLibraryNames) {
    library = dlopen(name, RTLD_NOW | RTLD_LOCAL);
    if (library != nullptr) break;
  }
  if (library == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error(std::string("OSMesa: cannot load libOSMesa.so.8 (") +
                             (why != nullptr ? why : "not found") +
                             "); frames and rendered coverage need Mesa's libosmesa6");
  }
  // Never closed: GL state lives as long as the process. A definition already in the process
  // (an LD_PRELOAD stand-in, as tests/render use) comes first, as it would for a linked library.
  auto symbol = [library](const char* name) {
    void* address = dlsym(RTLD_DEFAULT, name);
    if (address == nullptr) address = dlsym(library, name);
    if (address == nullptr) {
      throw std::runtime_error(std::string("OSMesa: libOSMesa has no ") + name);
    }
    return address;
  };
  GlApi api;
  auto osmesa = [&](auto& entry, const char* name) {
    entry = reinterpret_cast<std::remove_reference_t<decltype(entry)>>(symbol(name));
  };
  osmesa(api.OSMesaCreateContextExt, "OSMesaCreateContextExt");
  osmesa(api.OSMesaDestroyContext, "OSMesaDestroyContext");
  osmesa(api.OSMesaMakeCurrent, "OSMesaMakeCurrent");
  osmesa(api.OSMesaGetCurrentContext, "OSMesaGetCurrentContext");
  const auto get_proc =
      reinterpret_cast<decltype(&::OSMesaGetProcAddress)>(symbol("OSMesaGetProcAddress"));
  auto gl = [&](auto& entry, const char* name) {
    OSMESAproc address = get_proc(name);
    if (address == nullptr) throw std::runtime_error(std::string("OSMesa: no GL function ") + name);
    entry = reinterpret_cast<std::remove_reference_t<decltype(entry)>>(address);
  };
  gl(api.AttachShader, "glAttachShader");
  gl(api.BindAttribLocation, "glBindAttribLocation");
  gl(api.BindBuffer, "glBindBuffer");
  gl(api.BlendFunc, "glBlendFunc");
  gl(api.BlendFuncSeparate, "glBlendFuncSeparate");
  gl(api.BufferData, "glBufferData");
  gl(api.BufferSubData, "glBufferSubData");
  gl(api.Clear, "glClear");
  gl(api.ClearColor, "glClearColor");
  gl(api.CompileShader, "glCompileShader");
  gl(api.CreateProgram, "glCreateProgram");
  gl(api.CreateShader, "glCreateShader");
  gl(api.DeleteShader, "glDeleteShader");
  gl(api.Disable, "glDisable");
  gl(api.DrawArrays, "glDrawArrays");
  gl(api.Enable, "glEnable");
  gl(api.EnableVertexAttribArray, "glEnableVertexAttribArray");
  gl(api.Finish, "glFinish");
  gl(api.GenBuffers, "glGenBuffers");
  gl(api.GetProgramiv, "glGetProgramiv");
  gl(api.GetShaderInfoLog, "glGetShaderInfoLog");
  gl(api.GetShaderiv, "glGetShaderiv");
  gl(api.GetUniformLocation, "glGetUniformLocation");
  gl(api.LinkProgram, "glLinkProgram");
  gl(api.ShaderSource, "glShaderSource");
  gl(api.Uniform1f, "glUniform1f");
  gl(api.Uniform2f, "glUniform2f");
  gl(api.UseProgram, "glUseProgram");
  gl(api.VertexAttribPointer, "glVertexAttribPointer");
  gl(api.Viewport, "glViewport");
  return api;
}

}  // namespace

const GlApi& glApi() {
  static const GlApi api = load();
  return api;
}

}  // namespace canopy::render::internal
