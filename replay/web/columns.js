// The page's data as it is embedded (replay/replay_data.h): gzipped, in base64, a JSON header
// and typed columns after it. readData inflates it with the browser's own DecompressionStream
// and turns the columns into the arrays decode.js reads: positions in metres, headings in
// radians (Float64Array), and the maps', plans' and tracks' columns.
/* global CanopyReplay, DecompressionStream */
(function () {
  "use strict";

  const MISSING = -2147483648;  // an Int32 column's missing number (replay/columns.h)
  const LITTLE = new Uint8Array(new Uint32Array([1]).buffer)[0] === 1;

  // A column's values as a typed array: Int32 or Float32, little-endian in the data. An
  // "i32delta" column holds runs of `stride` values, each after the first as its change since
  // the one before: added up again here.
  function column(buffer, offset, c) {
    const float = c.type === "f32";
    let out;
    if (LITTLE) {
      out = float ? new Float32Array(buffer, offset, c.count) : new Int32Array(buffer, offset, c.count);
    } else {
      const view = new DataView(buffer);
      out = float ? new Float32Array(c.count) : new Int32Array(c.count);
      for (let n = 0; n < c.count; n++) {
        out[n] = float ? view.getFloat32(offset + 4 * n, true) : view.getInt32(offset + 4 * n, true);
      }
    }
    if (c.type === "i32delta" && c.stride > 0) {
      out = Int32Array.from(out);
      for (let n = 0; n < c.count; n++) {
        if (n % c.stride !== 0) out[n] = (out[n - 1] + out[n]) | 0;
      }
    }
    return out;
  }

  // Int32 fixed point (cm, mrad) → Float64 in metres or radians, missing → NaN.
  function scaled(values, unit) {
    const out = new Float64Array(values.length);
    for (let n = 0; n < values.length; n++) out[n] = values[n] === MISSING ? NaN : values[n] / unit;
    return out;
  }

  // Columns stored [entity][step] (stride S) → one Float64Array [step][entity][field].
  function interleave(S, N, fields, unit) {
    const out = new Float64Array(S * N * fields.length);
    fields.forEach(function (values, f) {
      for (let e = 0; e < N; e++) {
        for (let k = 0; k < S; k++) {
          const v = values[e * S + k];
          out[(k * N + e) * fields.length + f] = v === MISSING ? NaN : v / unit[f];
        }
      }
    });
    return out;
  }

  // The header and its columns (an ArrayBuffer of the inflated data) → the object decode.js
  // reads: the header's fields, and trees, uav, target, mapColumns, planColumns, trackColumns.
  CanopyReplay.readColumns = function (buffer) {
    const n = new DataView(buffer).getUint32(0, true);
    const raw = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 4, n)));
    if (raw.format !== 3) throw new Error("replay data of format " + raw.format + ", this page reads 3");
    const c = {};
    raw.columns.forEach(function (d) { c[d.name] = column(buffer, 4 + n + d.offset, d); });
    const S = raw.steps, A = raw.agents.length, T = raw.targets.length;
    const tx = scaled(c.tree_x, 100), ty = scaled(c.tree_y, 100), tr = scaled(c.tree_r, 100);
    raw.trees = { length: tx.length, x: tx, y: ty, r: tr };  // crowns' centres and radii (m)
    raw.uav = interleave(S, A, [c.uav_x, c.uav_y, c.uav_yaw], [100, 100, 1000]);
    if (c.uav_z) raw.uav_z = interleave(S, A, [c.uav_z], [100]);  // altitudes (issue 53)
    raw.target = interleave(S, T, [c.target_x, c.target_y], [100, 100]);
    // Tracks: track_count[k * A + a] of them at (k, a), in order. They stay columns (decode.js
    // makes the objects of one (k, a) when asked); copied out, so that the inflated data can
    // be collected. start[k * A + a]: the first track of (k, a).
    const start = new Int32Array(S * A + 1);
    for (let id = 0; id < S * A; id++) start[id + 1] = start[id] + c.track_count[id];
    // The maps' columns (replay/replay_changes.cpp: their layout) stay too, copied out.
    raw.mapColumns = {};
    ["set_count", "removed_count", "set_key", "set_x", "set_y", "set_r", "outline_count", "outline_x", "outline_y",
      "removed_key"].forEach(function (name) { raw.mapColumns[name] = c["map_" + name].slice(); });
    raw.planColumns = c;  // decode.js reads the plan_, epoch_, part_ and message_ columns
    raw.trackColumns = { start: start };
    ["key", "label", "target", "x", "y", "vx", "vy", "pxx", "pxy", "pyy"].forEach(function (name) {
      raw.trackColumns[name] = c["track_" + name].slice();
    });
    return raw;
  };

  // Resolves to the page's data (readColumns of the element `id`, #replay-data unless given),
  // or to null when the page has no such element.
  CanopyReplay.readData = function (id) {
    const element = document.getElementById(id || "replay-data");
    if (!element) return Promise.resolve(null);
    const text = atob(element.textContent.trim()), bytes = new Uint8Array(text.length);
    for (let i = 0; i < text.length; i++) bytes[i] = text.charCodeAt(i);
    const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("gzip"));
    return new Response(stream).arrayBuffer().then(function (buffer) {
      if (!id) CanopyReplay.dataBytes = buffer.byteLength;  // the inflated size, which the tests report
      const raw = CanopyReplay.readColumns(buffer);
      // In a page comparing two runs: which run this is ("A", "B") and its folder (compare.js).
      raw.letter = element.getAttribute("data-run");
      raw.folder = element.getAttribute("data-folder");
      return raw;
    });
  };
})();
