// Height (issue 53): a UAV that flies at an altitude shows it. Its footprint is drawn at the
// altitude of the step (a pinhole camera's ground footprint is proportional to the altitude, so
// the start footprint scaled by z_k / z_0), its name carries "40 m", and the timeline can plot its
// altitude over the run. A run without altitudes (no uav_z column) is drawn as before.
/* global CanopyReplay */
(function () {
  "use strict";

  // Agent i's altitude at step k (m), or NaN when it has none.
  function altitude(run, k, i) {
    return run.altitude ? run.altitude(k, i) : NaN;
  }

  // Agent i's footprint at step k: the model's (at its start altitude z0) scaled by z_k / z0.
  CanopyReplay.footprintAt = function (run, k, i) {
    const agent = run.agents[i], f = agent.footprint, z = altitude(run, k, i);
    if (!(agent.z > 0) || !isFinite(z) || z === agent.z) return f;
    const scale = z / agent.z;
    const out = Object.assign({}, f);
    if (f.size) out.size = [f.size[0] * scale, f.size[1] * scale];
    if (f.corners) out.corners = f.corners.map(function (q) { return [q[0] * scale, q[1] * scale]; });
    if (f.radius !== undefined) out.radius = f.radius * scale;
    return out;
  };

  // " 40 m" after the name of an agent with an altitude, else "".
  CanopyReplay.altitudeText = function (run, k, i) {
    const z = altitude(run, k, i);
    return isFinite(z) ? " " + Math.round(z) + " m" : "";
  };

  // The timeline's field of agent i's altitude, when it has one.
  CanopyReplay.altitudeFields = function (run, i) {
    if (!run.altitude || !(run.agents[i].z > 0)) return [];
    return [{ id: "altitude", label: "altitude (m)", values: function () {
      const out = new Float64Array(run.steps);
      for (let k = 0; k < run.steps; k++) out[k] = run.altitude(k, i);
      return out;
    } }];
  };
})();
