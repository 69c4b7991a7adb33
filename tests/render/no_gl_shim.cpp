// Preloaded (LD_PRELOAD) into `canopy` by test_render_cli: any attempt to create a GL context
// ends the process at once with exit code 86, so a run that succeeds under it created none.
#include <GL/osmesa.h>
#include <unistd.h>

#include <cstdio>

extern "C" OSMesaContext OSMesaCreateContextExt(GLenum, GLint, GLint, GLint, OSMesaContext) {
  std::fputs("no_gl_shim: a GL context was requested\n", stderr);
  _exit(86);
}
