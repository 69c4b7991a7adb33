// What the browser tests expect, derived from a run's own files (record.jsonl or, at city scale,
// `canopy record` of record.jsonl.zst; summary.json, manifest.json), never from the page.
"use strict";

const fs = require("fs");
const path = require("path");

// The UAV palette of the PNG frames (render/colour.cpp, uavColour), repeating after 8.
const PALETTE = [[31, 119, 180], [230, 120, 20], [148, 103, 189], [214, 39, 40],
  [23, 170, 190], [140, 86, 75], [227, 119, 194], [188, 170, 34]];

// The canopy program, for `canopy record DIR`: a run at city scale writes record.jsonl.zst.
let canopyBinary = null;
function setCanopy(binary) { canopyBinary = binary; }

// The record's JSON lines: record.jsonl, or what `canopy record` prints of record.jsonl.zst.
function recordText(dir) {
  if (fs.existsSync(path.join(dir, "record.jsonl"))) return fs.readFileSync(path.join(dir, "record.jsonl"), "utf8");
  const r = require("child_process").spawnSync(canopyBinary, ["record", dir],
    { encoding: "utf8", maxBuffer: 1 << 30 });
  if (r.status !== 0) throw new Error("canopy record " + dir + ": " + r.stderr);
  return r.stdout;
}

function readRun(dir) {
  const record = recordText(dir).split("\n")
    .filter((l) => l.trim()).map((l) => JSON.parse(l));
  const summary = JSON.parse(fs.readFileSync(path.join(dir, "summary.json"), "utf8"));
  const config = JSON.parse(fs.readFileSync(path.join(dir, "manifest.json"), "utf8")).effective_config;
  return { record, summary, config };
}

// m-Ownership (paper Def. 1 as docs/design-notes.md reads it): i owns t at k iff t is visible to
// i at every step k .. k+m-1; near the end the last full window decides.
function owners(run, k, t) {
  const K = run.record.length - 1, m = run.config.analysis.m;
  const first = Math.min(k, Math.max(0, K - m + 1)), last = Math.min(K, first + m - 1);
  const out = [];
  run.config.uavs.forEach((uav, i) => {
    let all = true;
    for (let h = first; h <= last; h++) {
      if (run.record[h].scans[i].visible.indexOf(t) < 0) all = false;
    }
    if (all) out.push(uav.name);
  });
  return out;
}

// Agent a's track standing for target t at step k: same label, nearest first, each track and
// target taken once, within the OSPA cut-off (50 m).
function trackOf(run, k, a, t) {
  const line = run.record[k], tracks = line.agents[a].tracks, pairs = [];
  line.targets.forEach((target, ti) => {
    const label = run.config.targets[ti].label;
    tracks.forEach((track, j) => {
      const d = Math.hypot(track.x[0] - target.p[0], track.x[1] - target.p[1]);
      if (track.label === label && d <= 50) pairs.push([d, ti, j]);
    });
  });
  pairs.sort((x, y) => x[0] - y[0] || x[1] - y[1] || x[2] - y[2]);
  const takenTarget = new Set(), takenTrack = new Set();
  for (const [, ti, j] of pairs) {
    if (takenTarget.has(ti) || takenTrack.has(j)) continue;
    takenTarget.add(ti);
    takenTrack.add(j);
    if (ti === t) return tracks[j];
  }
  return null;
}

// The timeline's values of target t at step k, seen through agent a.
function targetAt(run, k, a, t) {
  const names = run.config.uavs.map((u) => u.name), line = run.record[k];
  const track = trackOf(run, k, a, t);
  return {
    k: String(k), target: run.config.targets[t].name, agent: names[a],
    covered: names.filter((n, i) => line.scans[i].in_footprint.indexOf(t) >= 0).join(","),
    visible: names.filter((n, i) => line.scans[i].visible.indexOf(t) >= 0).join(","),
    owners: owners(run, k, t).join(","),
    trace: track ? track.P[0] + track.P[4] : null,  // P packed [P00, P01, P02, P03, P11, ...]
    ospa: run.summary.uavs[a].ospa_m[k]
  };
}

// The footprint's outline (m) of agent i at step k, from its pose and the scenario's fov.
function footprint(run, k, i) {
  const uav = run.config.uavs[i], pose = run.record[k].uavs[i];
  const c = Math.cos(pose.yaw), s = Math.sin(pose.yaw), [x, y] = pose.p;
  if (uav.fov.size) {
    const hw = uav.fov.size[0] / 2, hh = uav.fov.size[1] / 2;
    return [[hw, hh], [-hw, hh], [-hw, -hh], [hw, -hh]]
      .map(([u, v]) => [x + c * u - s * v, y + s * u + c * v]);
  }
  if (uav.fov.range) {
    const out = [[x, y]], half = uav.fov.angle / 2;
    for (let n = 0; n <= 180; n++) {
      const a = pose.yaw - half + (2 * half * n) / 180;
      out.push([x + uav.fov.range * Math.cos(a), y + uav.fov.range * Math.sin(a)]);
    }
    return out;
  }
  const out = [];
  for (let n = 0; n < 180; n++) {
    const a = (2 * Math.PI * n) / 180;
    out.push([x + uav.fov.radius * Math.cos(a), y + uav.fov.radius * Math.sin(a)]);
  }
  return out;
}

module.exports = { PALETTE, setCanopy, readRun, owners, trackOf, targetAt, footprint };
