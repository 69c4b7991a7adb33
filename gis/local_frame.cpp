#include "gis/local_frame.h"

#include <proj.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace canopy::gis {

struct Projector::Impl {
  PJ_CONTEXT* context = nullptr;
  PJ* transform = nullptr;
  ~Impl() {
    if (transform) proj_destroy(transform);
    if (context) proj_context_destroy(context);
  }
};

Projector::Projector(const std::string& source, const std::string& target)
    : impl_(std::make_unique<Impl>()) {
  impl_->context = proj_context_create();
  proj_log_level(impl_->context, PJ_LOG_NONE);
  PJ* raw = proj_create_crs_to_crs(impl_->context, source.c_str(), target.c_str(), nullptr);
  if (!raw) {
    throw std::runtime_error(std::string("PROJ cannot transform between these CRSs: ") +
                             proj_context_errno_string(impl_->context,
                                                       proj_context_errno(impl_->context)));
  }
  // x = easting / longitude, y = northing / latitude, whatever the CRSs' declared axis order.
  impl_->transform = proj_normalize_for_visualization(impl_->context, raw);
  proj_destroy(raw);
  if (!impl_->transform) throw std::runtime_error("PROJ cannot normalise the axis order");
}

Projector::~Projector() = default;
Projector::Projector(Projector&&) noexcept = default;
Projector& Projector::operator=(Projector&&) noexcept = default;

Vec2 Projector::operator()(const Vec2& xy) const {
  PJ_COORD in = proj_coord(xy.x(), xy.y(), 0.0, 0.0);
  const PJ_COORD out = proj_trans(impl_->transform, PJ_FWD, in);
  if (!std::isfinite(out.xy.x) || !std::isfinite(out.xy.y))
    throw std::runtime_error("PROJ cannot transform this point");
  return {out.xy.x, out.xy.y};
}

std::string localTransverseMercator(double lat, double lon) {
  char text[256];
  std::snprintf(text, sizeof text,
                "+proj=tmerc +lat_0=%.10f +lon_0=%.10f +k=1 +x_0=0 +y_0=0 +datum=WGS84 "
                "+units=m +no_defs +type=crs",
                lat, lon);
  return text;
}

bool isMetricProjected(const std::string& wkt) {
  PJ_CONTEXT* context = proj_context_create();
  proj_log_level(context, PJ_LOG_NONE);
  bool metric = false;
  if (PJ* crs = proj_create(context, wkt.c_str())) {
    PJ* horizontal = crs;
    if (proj_get_type(crs) == PJ_TYPE_COMPOUND_CRS) horizontal = proj_crs_get_sub_crs(context, crs, 0);
    if (horizontal && proj_get_type(horizontal) == PJ_TYPE_PROJECTED_CRS) {
      if (PJ* cs = proj_crs_get_coordinate_system(context, horizontal)) {
        double factor = 0.0;
        metric = proj_cs_get_axis_count(context, cs) >= 2;
        for (int axis = 0; axis < 2 && metric; ++axis) {
          proj_cs_get_axis_info(context, cs, axis, nullptr, nullptr, nullptr, &factor, nullptr,
                                nullptr, nullptr);
          metric = factor == 1.0;
        }
        proj_destroy(cs);
      }
    }
    if (horizontal && horizontal != crs) proj_destroy(horizontal);
    proj_destroy(crs);
  }
  proj_context_destroy(context);
  return metric;
}

std::string crsName(const std::string& wkt) {
  PJ_CONTEXT* context = proj_context_create();
  proj_log_level(context, PJ_LOG_NONE);
  std::string name = "unnamed CRS";
  if (PJ* crs = proj_create(context, wkt.c_str())) {
    if (const char* n = proj_get_name(crs)) name = n;
    const char* authority = proj_get_id_auth_name(crs, 0);
    const char* code = proj_get_id_code(crs, 0);
    if (authority && code) name = std::string(authority) + ":" + code + " (" + name + ")";
    proj_destroy(crs);
  }
  proj_context_destroy(context);
  return name;
}

}  // namespace canopy::gis
