#pragma once
// A cairo write function that appends a document's bytes to a std::string (the closure), for
// cairo_{pdf,svg}_surface_create_for_stream: frames (render/scene_vector.cpp) and figures
// (analysis/figure_pdf.cpp) are built in memory and written whole.
#include <cairo.h>

#include <string>

namespace canopy::render {

inline cairo_status_t appendToString(void* closure, const unsigned char* data,
                                     unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace canopy::render
