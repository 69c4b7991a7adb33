#include "render/run_coverage.h"

#include <vector>

#include "render/coverage.h"
#include "render/frame_writer.h"
#include "sim/record_reader.h"

namespace canopy::render {

std::string coverageCsvOfRun(const std::filesystem::path& run_dir,
                             std::optional<render::ImageSize> size, const sim::LineRange& steps) {
  const sim::RunRecord run = sim::readRun(run_dir, steps);
  const spec::ScenarioSpec& spec = run.spec;

  std::vector<sensing::SensorDef> sensors;
  for (const spec::UavSpec& uav : spec.uavs) sensors.push_back(uav.sensor);
  std::vector<std::string> names;
  for (const spec::TargetSpec& target : spec.targets) names.push_back(target.name);
  render::CoverageCounter counter(
      spec.aoi, size.value_or(render::fitSize(spec.aoi, render::kDefaultFrameLongSide)),
      spec.trees);
  std::string csv = render::coverageCsvHeader(names) + "\n";
  for (const world::WorldSnapshot& step : run.truth) {
    csv += render::coverageCsvRow(step.step, step.time,
                                  counter.count(step, sensors, spec.sensing.occlusion_model)) +
           "\n";
  }
  return csv;
}

}  // namespace canopy::render
