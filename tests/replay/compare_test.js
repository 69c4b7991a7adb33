// Two runs compared (`canopy view A B`, overlaid and side by side) in Debian's headless chromium,
// checked against both runs' own files: run B's tracks, plans and occlusion map drawn over A with
// A's layers and beliefs where B's record puts them, B's numbers beside A's, the legend and the
// map naming each run; side by side, the layers, beliefs, selection and plot set in one page are
// set in the other, and each page draws its run's tracks where its record puts them.
// Run B is the probe with two trees moved 4 m east, its people 3 m north, another seed and half
// the step, so that its maps, plans and tracks lie apart from A's and one time is a different
// step in each.
// Usage: node compare_test.js CANOPY_BINARY SOURCE_DIR WORK_DIR
// Exit 0 all passed, 1 a failure, 77 (ctest's skip) when chromium is not installed.
"use strict";

const fs = require("fs");
const path = require("path");
const { Browser, Page } = require("./cdp.js");
const expect = require("./record.js");
const { setCanopy, chromiumOrSkip, check, assert, canopyRun, mapPixels, finish, crashed } = require("./harness.js");

const [canopy, source, work] = process.argv.slice(2);
expect.setCanopy(canopy);
setCanopy(canopy);
const chromium = chromiumOrSkip();

// B's step at A's step k: the same time, round(k dt_A / dt_B), within B's run.
const stepOfB = (a, b, k) => Math.min(b.record.length - 1, Math.round((k * a.config.clock.dt) / b.config.clock.dt));

// The pixels that only one of B's layers drew: those that change when B is shown with the layer
// on (y against x, B hidden) but not when B is shown with it off (z against w): B's darts, drawn
// whatever the layers, change in both and are left out. A mask of 1 byte per pixel.
function onlyLayer(x, y, z, w) {
  const mask = new Uint8Array(x.w * x.h);
  const differ = (p, q, o) => p.data[o] !== q.data[o] || p.data[o + 1] !== q.data[o + 1] || p.data[o + 2] !== q.data[o + 2];
  for (let n = 0; n < mask.length; n++) mask[n] = differ(x, y, 4 * n) && !differ(w, z, 4 * n) ? 1 : 0;
  return { mask, w: x.w, h: x.h };
}

// How many pixels of the mask lie within r px (a square) of (px, py).
function countNear(m, px, py, r) {
  let n = 0;
  for (let y = Math.max(0, py - r); y <= Math.min(m.h - 1, py + r); y++) {
    for (let x = Math.max(0, px - r); x <= Math.min(m.w - 1, px + r); x++) n += m.mask[y * m.w + x];
  }
  return n;
}

// Where B's occlusion-map entry lies, sampled: 16 points on its circle, or 4 on each outline edge.
function entrySamples(e) {
  const [cx, cy, r] = e.x, out = [];
  if (e.outline) {
    e.outline.forEach((v, n) => {
      const u = e.outline[(n + 1) % e.outline.length];
      for (let f = 0; f < 4; f++) out.push([cx + v[0] + ((u[0] - v[0]) * f) / 4, cy + v[1] + ((u[1] - v[1]) * f) / 4]);
    });
  } else {
    for (let n = 0; n < 16; n++) out.push([cx + r * Math.cos((n * Math.PI) / 8), cy + r * Math.sin((n * Math.PI) / 8)]);
  }
  return out;
}

async function main() {
  fs.mkdirSync(work, { recursive: true });
  const probe = path.join(source, "tests/replay/data/replay_probe.json");
  const dirA = path.join(work, "probe"), dirB = path.join(work, "probe_b");
  canopyRun(["run", probe, "--out", dirA]);
  canopyRun(["run", probe, "--set", "occluders.0.centre=[-4,3]", "--set", "occluders.1.centre=[14,4]",
    "--set", "targets.0.path.start=[-22,5]", "--set", "targets.1.path.start=[4,13]", "--set", "targets.2.path.start=[18,-7]",
    "--set", "targets.3.path.start=[-12,-13]", "--set", "seed=8", "--set", "clock.dt=0.1", "--out", dirB]);
  const A = expect.readRun(dirA), B = expect.readRun(dirB), names = A.config.uavs.map((u) => u.name);
  const overlay = path.join(work, "overlay.html"), side = path.join(work, "side_by_side.html");
  canopyRun(["view", dirA, dirB, "--overlay", "--out", overlay]);
  canopyRun(["view", dirA, dirB, "--out", side]);

  const browser = new Browser(chromium);
  try {
    const page = await Page.open(browser, 1280, 900);
    await page.navigate("file://" + path.resolve(overlay));
    await page.evaluate("CanopyReplay.ready");

    await check("overlay: B's tracks, occlusion map and plans, through its agent of the shown one's name, are B's record's at its step", async () => {
      let checked = 0;
      for (const k of [0, 17, 30, A.record.length - 1]) {
        for (let a = 0; a < names.length; a++) {
          const got = await page.evaluate(`(() => { const app = CanopyReplay.app; app.setAgent(${a}); app.setStep(${k});
            return CanopyReplay.secondStats; })()`);
          const kB = stepOfB(A, B, k), line = B.record[kB], b = B.config.uavs.findIndex((u) => u.name === names[a]);
          const planPoints = line.agents.reduce((s, agent) => s + agent.planned_path.length, 0);
          assert(got.k === kB && got.agent === b, `A's k=${k}, ${names[a]}: B drawn at k=${got.k} through agent ${got.agent}, want ${kB}, ${b}`);
          assert(got.tracks === line.agents[b].tracks.length, `k=${k} ${names[a]}: ${got.tracks} of B's tracks drawn, B's record holds ${line.agents[b].tracks.length}`);
          assert(got.mapEntries === line.agents[b].map.length, `k=${k} ${names[a]}: ${got.mapEntries} map entries, B's record ${line.agents[b].map.length}`);
          assert(got.planPoints === planPoints, `k=${k}: ${got.planPoints} planned points of B, B's record ${planPoints}`);
          checked++;
        }
      }
      // A layer switched off is off for B too.
      const off = await page.evaluate(`(() => { const app = CanopyReplay.app; ["tracks", "map", "plans"].forEach((l) => app.setLayer(l, false));
        const s = CanopyReplay.secondStats; ["tracks", "map", "plans"].forEach((l) => app.setLayer(l, true)); return s; })()`);
      assert(off.tracks === 0 && off.mapEntries === 0 && off.planPoints === 0, "B drawn with its layers off: " + JSON.stringify(off));
      assert(checked === 4 * names.length, checked + " steps and agents checked");
    });

    await check("overlay: B's tracks, map entries and planned points drawn where B's record puts them", async () => {
      const k = 30, a = 1, kB = stepOfB(A, B, k), line = B.record[kB];
      await page.evaluate(`(() => { const app = CanopyReplay.app; app.setAgent(${a}); app.setStep(${k}); })()`);
      // Every layer off but one; the four images of onlyLayer.
      const images = async (layer) => {
        const set = async (second, on) => {
          await page.evaluate(`(() => { const app = CanopyReplay.app; CanopyReplay.LAYERS.forEach((l) => { app.state.layers[l.id] = false; });
            app.state.layers.${layer} = ${on}; app.setSecond(${second}); })()`);
          return mapPixels(page);
        };
        return onlyLayer(await set(false, true), await set(true, true), await set(true, false), await set(false, false));
      };
      const toPixel = (x, y) => page.evaluate(`CanopyReplay.app.view.toPixel(${x}, ${y})`);
      const darts = [];
      for (const u of line.uavs) darts.push(await toPixel(u.p[0], u.p[1]));
      const nearDart = (p) => darts.some((d) => Math.hypot(d.x - p.x, d.y - p.y) < 12);
      // Tracks: each a "+" of 6 px arms at its mean.
      const tracks = await images("tracks");
      let tested = 0, drawn = 0;
      for (const t of line.agents[a].tracks) {
        const p = await toPixel(t.x[0], t.x[1]);
        if (nearDart(p)) continue;
        tested++;
        if (countNear(tracks, p.x, p.y, 7) >= 4) drawn++;
      }
      assert(tested >= 2 && drawn === tested, `${drawn} of ${tested} of B's tracks (clear of its darts) drawn at their means`);
      // The occlusion map: its entries apart (> 1 m) from every entry of A's map, a dashed
      // outline through at least a quarter of their samples.
      const map = await images("map"), mapA = A.record[k].agents[a].map;
      let entries = 0, outlined = 0;
      for (const e of line.agents[a].map) {
        if (mapA.some((f) => Math.hypot(f.x[0] - e.x[0], f.x[1] - e.x[1]) <= 1)) continue;
        entries++;
        let hit = 0;
        const samples = entrySamples(e);
        for (const [x, y] of samples) {
          const p = await toPixel(x, y);
          if (countNear(map, p.x, p.y, 1) > 0) hit++;
        }
        if (hit >= samples.length / 4) outlined++;
      }
      assert(entries >= 1 && outlined === entries, `${outlined} of ${entries} of B's map entries apart from A's outlined`);
      // Plans: a ring of radius 3 px at each planned point.
      const plans = await images("plans");
      let points = 0, ringed = 0;
      for (const agent of line.agents) {
        for (const q of agent.planned_path) {
          const p = await toPixel(q[0], q[1]);
          if (nearDart(p)) continue;
          points++;
          if (countNear(plans, p.x, p.y, 4) >= 3) ringed++;
        }
      }
      assert(points >= 4 && ringed >= points - 1, `${ringed} of ${points} of B's planned points ringed`);
      await page.evaluate(`(() => { const app = CanopyReplay.app; CanopyReplay.LAYERS.forEach((l) => { app.state.layers[l.id] = true; });
        app.setSecond(true); })()`);
    });

    await check("overlay: A's selection selects B's agent of that name; B's numbers beside A's are B's record's", async () => {
      for (const [k, i] of [[12, 0], [31, 2], [47, 3]]) {
        const got = await page.evaluate(`(() => { const app = CanopyReplay.app; app.setStep(${k}); app.select({ kind: "agent", index: ${i} });
          return { stats: CanopyReplay.secondStats, numbers: Object.assign({}, document.getElementById("numbers-b").dataset),
            title: document.getElementById("numbers-b").textContent }; })()`);
        const kB = stepOfB(A, B, k), b = B.config.uavs.findIndex((u) => u.name === names[i]);
        let plan = null;
        for (let h = kB; h >= 0 && !plan; h--) if (B.record[h].plan) plan = B.record[h].plan;
        const part = plan && plan.agents.find((q) => q.agent === b);
        assert(got.stats.selection && got.stats.selection.kind === "agent" && got.stats.selection.index === b, "B's selection " + JSON.stringify(got.stats.selection));
        assert(got.numbers.kind === "agent" && +got.numbers.tracks === B.record[kB].agents[b].tracks.length,
          `k=${k} ${names[i]}: B's numbers show ${got.numbers.tracks} tracks, B's record ${B.record[kB].agents[b].tracks.length}`);
        assert(part ? Math.abs(+got.numbers.cost - part.cost) <= 5e-4 * Math.abs(part.cost) : got.numbers.cost === "",
          `k=${k} ${names[i]}: B's cost ${got.numbers.cost}, B's record ${part && part.cost}`);
        assert(got.title.indexOf("run B (probe_b)") >= 0 && got.title.indexOf("at k = " + kB) >= 0, "B's numbers: " + got.title.slice(0, 120));
      }
    });

    await check("overlay: a plotted field of B's counterpart dashed over A's, and B's nearest track in the hover readout, are B's record's", async () => {
      const i = 2, t = 1, a = 0, K = A.record.length;
      const plotted = (id) => page.evaluate(`(() => { CanopyReplay.app.setPlot("${id}");
        const s = CanopyReplay.app.series; return s.traceB ? Array.from(s.traceB) : null; })()`);
      await page.evaluate(`CanopyReplay.app.select({ kind: "agent", index: ${i} })`);
      const want = {
        tracks: (kB) => B.record[kB].agents[i].tracks.length,
        trace: (kB) => B.record[kB].agents[i].tracks.reduce((sum, tr) => sum + tr.P[0] + tr.P[4], 0)
      };
      for (const id of Object.keys(want)) {
        const got = await plotted(id);
        assert(got && got.length === K, `${id}: B's trace ${got && got.length} values for ${K} steps`);
        for (let k = 0; k < K; k++) {
          const w = want[id](stepOfB(A, B, k));
          assert(Math.abs(got[k] - w) <= 2e-3 * Math.abs(w) + 1e-6, `B's ${id} at A's k=${k}: ${got[k]}, B's record ${w}`);
        }
      }
      await page.evaluate(`(() => { const app = CanopyReplay.app; app.setAgent(${a}); app.select({ kind: "target", index: ${t} }); })()`);
      const error = await plotted("error");
      for (let k = 0; k < K; k++) {
        const kB = stepOfB(A, B, k), tr = expect.trackOf(B, kB, a, t), q = B.record[kB].targets[t].p;
        const w = tr ? Math.hypot(tr.x[0] - q[0], tr.x[1] - q[1]) : NaN;
        assert(Number.isNaN(w) ? error[k] === null || Number.isNaN(error[k]) : Math.abs(error[k] - w) <= 0.02,
          `the error of B's track of ${B.config.targets[t].name} at A's k=${k}: ${error[k]}, B's record ${w}`);
      }
      // The hover readout: B's nearest track of its agent a at its step, and its distance.
      const k = 30, kB = stepOfB(A, B, k);
      await page.evaluate(`CanopyReplay.app.setStep(${k})`);
      const rect = await page.evaluate(`(() => { const r = document.getElementById("map").getBoundingClientRect();
        return { x: r.left, y: r.top }; })()`);
      for (const [fx, fy] of [[0.3, 0.4], [0.55, 0.5], [0.7, 0.62]]) {
        const v = await page.evaluate("(({ cx, cy, scale, width, height }) => ({ cx, cy, scale, width, height }))(CanopyReplay.app.view)");
        const px = Math.round(rect.x + v.width * fx), py = Math.round(rect.y + v.height * fy);
        await page.send("Input.dispatchMouseEvent", { type: "mouseMoved", x: px, y: py });
        const got = await page.evaluate(`document.getElementById("hover").dataset.trackB`);
        const x = v.cx + (px - rect.x - v.width / 2) / v.scale, y = v.cy - (py - rect.y - v.height / 2) / v.scale;
        const best = B.record[kB].agents[a].tracks.map((tr) => ({ key: tr.key.join(":"), d: Math.hypot(tr.x[0] - x, tr.x[1] - y) }))
          .sort((p, q) => p.d - q.d)[0];
        const parts = got.split(":");
        assert(parts.slice(0, 2).join(":") === best.key && Math.abs(+parts[2] - best.d) <= 0.02,
          `B's nearest track at (${x.toFixed(2)}, ${y.toFixed(2)}): ${got}, B's record ${best.key} at ${best.d}`);
      }
      await page.send("Input.dispatchMouseEvent", { type: "mouseMoved", x: 2, y: 2 });
    });

    await check("overlay: the legend and the map say which run is which (letter, folder, scenario, seed)", async () => {
      const got = await page.evaluate(`(() => { const svg = CanopyReplay.exportSvg(CanopyReplay.app);
        const texts = Array.from(new DOMParser().parseFromString(svg, "image/svg+xml").querySelectorAll("text")).map((t) => t.textContent);
        return { a: document.getElementById("run-a-entry").textContent, b: document.getElementById("run-b-entry").textContent, texts }; })()`);
      const title = (run, letter, folder) => `run ${letter} (${folder}): ${run.config.name}, seed ${run.config.seed}`;
      assert(got.a.startsWith(title(A, "A", "probe")), "the legend's run A: " + got.a);
      assert(got.b.startsWith(title(B, "B", "probe_b")) && got.b.indexOf("hollow darts") >= 0, "the legend's run B: " + got.b);
      assert(got.texts.some((t) => t.startsWith("run A: " + A.config.name)) && got.texts.some((t) => t.startsWith("run B over it")),
        "the map's panel: " + got.texts.slice(0, 3).join(" | "));
      assert(page.errors.length === 0, page.errors.join("\n"));
    });

    await check("side by side: layers, beliefs, selection and plot set in one page are set in the other; legends name both runs", async () => {
      const tab = await Page.open(browser, 1600, 900);
      await tab.navigate("file://" + path.resolve(side));
      await tab.evaluate("CanopySideBySide.ready");
      const frame = (n) => `document.getElementById("run-${n}").contentWindow`;
      const state = `CanopySideBySide.apps.map((app) => ({ layers: Object.assign({}, app.state.layers), agent: app.state.agent,
        sel: app.state.selection, plot: app.state.plot }))`;
      // A switch clicked in B's page, a key pressed in A's.
      const got = await tab.evaluate(`(() => { ${frame("b")}.document.getElementById("layer-links").click();
        ${frame("a")}.document.dispatchEvent(new KeyboardEvent("keydown", { key: "5", code: "Digit5", bubbles: true }));
        const apps = CanopySideBySide.apps; apps[1].setAgent(3); apps[0].select({ kind: "target", index: 2 }); apps[1].setPlot("error");
        return ${state}; })()`);
      got.forEach((s, n) => {
        assert(s.layers.links === false && s.layers.map === false && s.layers.tracks === true, `page ${n}: layers ${JSON.stringify(s.layers)}`);
        assert(s.agent === 3 && s.sel && s.sel.kind === "target" && s.sel.index === 2 && s.plot === "error", `page ${n}: ${JSON.stringify(s)}`);
      });
      const legends = await tab.evaluate(`[0, 1].map((n) => document.getElementById(n ? "run-b" : "run-a").contentDocument.getElementById("run-entry").textContent)`);
      assert(legends[0].startsWith(`run A (probe): ${A.config.name}, seed ${A.config.seed}, this page; run B (probe_b)`), "A's legend: " + legends[0]);
      assert(legends[1].startsWith(`run B (probe_b): ${B.config.name}, seed ${B.config.seed}, this page; run A (probe)`), "B's legend: " + legends[1]);
      assert(tab.errors.length === 0, tab.errors.join("\n"));
      await tab.send("Page.close").catch(() => {});
    });

    await check("side by side: each page draws its own run's tracks where its record puts them (the switch in A's page)", async () => {
      const tab = await Page.open(browser, 1600, 900);
      await tab.navigate("file://" + path.resolve(side));
      await tab.evaluate("CanopySideBySide.ready");
      const k = 30, a = 1, kB = stepOfB(A, B, k);
      await tab.evaluate(`(() => { const apps = CanopySideBySide.apps; apps[0].setAgent(${a}); apps[0].setStep(${k}); })()`);
      const map = (n) => `document.getElementById("run-${n}").contentDocument.getElementById("map")`;
      const on = [await mapPixels(tab, map("a")), await mapPixels(tab, map("b"))];
      const drawn = await tab.evaluate(`["a", "b"].map((n) => document.getElementById("run-" + n).contentWindow.CanopyReplay.drawnTracks)`);
      await tab.evaluate(`document.getElementById("run-a").contentDocument.getElementById("layer-tracks").click()`);
      const off = [await mapPixels(tab, map("a")), await mapPixels(tab, map("b"))];
      [[A, k, "a"], [B, kB, "b"]].forEach(([run], n) => assert(drawn[n] === run.record[[k, kB][n]].agents[a].tracks.length,
        `page ${n}: ${drawn[n]} tracks drawn, its record ${run.record[[k, kB][n]].agents[a].tracks.length}`));
      for (const [n, run, kk] of [[0, A, k], [1, B, kB]]) {
        const changed = { mask: new Uint8Array(on[n].w * on[n].h), w: on[n].w, h: on[n].h };
        for (let p = 0; p < changed.mask.length; p++) {
          const o = 4 * p;
          changed.mask[p] = on[n].data[o] !== off[n].data[o] || on[n].data[o + 1] !== off[n].data[o + 1] || on[n].data[o + 2] !== off[n].data[o + 2] ? 1 : 0;
        }
        const win = `document.getElementById("run-${n ? "b" : "a"}").contentWindow`;
        const darts = [];
        for (const u of run.record[kk].uavs) darts.push(await tab.evaluate(`${win}.CanopyReplay.app.view.toPixel(${u.p[0]}, ${u.p[1]})`));
        let tested = 0, shown = 0;
        for (const t of run.record[kk].agents[a].tracks) {
          const p = await tab.evaluate(`${win}.CanopyReplay.app.view.toPixel(${t.x[0]}, ${t.x[1]})`);
          if (darts.some((d) => Math.hypot(d.x - p.x, d.y - p.y) < 12)) continue;
          tested++;
          if (countNear(changed, p.x, p.y, 7) >= 4) shown++;
        }
        assert(tested >= 2 && shown === tested, `page ${n}: ${shown} of ${tested} tracks (clear of the darts) changed with the switch`);
      }
      const both = await tab.evaluate("CanopySideBySide.apps.map((app) => app.state.layers.tracks)");
      assert(both[0] === false && both[1] === false, "the tracks switch: " + both);
      assert(tab.errors.length === 0, tab.errors.join("\n"));
    });
  } finally {
    await browser.close();
  }
  finish();
}

main().catch(crashed);
