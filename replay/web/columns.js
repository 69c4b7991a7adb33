// The page's data as it is embedded (replay/replay_data.h): gzipped, in base64, a JSON header
// and typed columns after it. readData inflates it with the browser's own DecompressionStream
// and turns the columns into the arrays decode.js reads: positions in metres, headings in
// radians (Float64Array), the tracks per step and agent, and the track of each person as one
// Int32Array.
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
  // reads: the header's fields, and trees, uav, target, tracks, track_of_target.
  CanopyReplay.readColumns = function (buffer) {
    const n = new DataView(buffer).getUint32(0, true);
    const raw = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 4, n)));
    if (raw.format !== 2) throw new Error("replay data of format " + raw.format + ", this page reads 2");
    const c = {};
    raw.columns.forEach(function (d) { c[d.name] = column(buffer, 4 + n + d.offset, d); });
    const S = raw.steps, A = raw.agents.length, T = raw.targets.length;
    const tx = scaled(c.tree_x, 100), ty = scaled(c.tree_y, 100), tr = scaled(c.tree_r, 100);
    raw.trees = new Float64Array(3 * tx.length);
    for (let i = 0; i < tx.length; i++) {
      raw.trees[3 * i] = tx[i];
      raw.trees[3 * i + 1] = ty[i];
      raw.trees[3 * i + 2] = tr[i];
    }
    raw.uav = interleave(S, A, [c.uav_x, c.uav_y, c.uav_yaw], [100, 100, 1000]);
    if (c.uav_z) raw.uav_z = interleave(S, A, [c.uav_z], [100]);  // altitudes (issue 53)
    raw.target = interleave(S, T, [c.target_x, c.target_y], [100, 100]);
    // Tracks: track_count[k * A + a] of them at (k, a), in order; the person each stands for
    // gives track_of_target [k][a][t] (-1: none).
    raw.tracks = [];
    raw.track_of_target = new Int32Array(S * A * T).fill(-1);
    const key = c.track_key, label = c.track_label, target = c.track_target;
    let j = 0;
    for (let k = 0; k < S; k++) {
      const perAgent = [];
      for (let a = 0; a < A; a++) {
        const list = [], count = c.track_count[k * A + a];
        for (let m = 0; m < count; m++, j++) {
          list.push({
            key: raw.keys[key[j]], label: raw.labels[label[j]],
            x: fixed(c.track_x[j]), y: fixed(c.track_y[j]), vx: fixed(c.track_vx[j]), vy: fixed(c.track_vy[j]),
            pxx: c.track_pxx[j], pxy: c.track_pxy[j], pyy: c.track_pyy[j]
          });
          if (target[j] >= 0) raw.track_of_target[(k * A + a) * T + target[j]] = m;
        }
        perAgent.push(list);
      }
      raw.tracks.push(perAgent);
    }
    return raw;
  };

  function fixed(v) { return v === MISSING ? NaN : v / 100; }

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
      return CanopyReplay.readColumns(buffer);
    });
  };
})();
