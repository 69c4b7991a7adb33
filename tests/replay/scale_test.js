// The replay page's data and drawing at scale in Debian's headless chromium, checked against the
// run's own files: the start view fills the map with what the run covers; the typed columns hold the record's poses, positions and tracks; the plans
// are copied from a cache while they do not change and look as when drawn directly; a crowd of people is drawn as squares without names; a second run
// drawn over the first (`view A B --overlay`) at its step of the same time.
// Usage: node scale_test.js CANOPY_BINARY SOURCE_DIR WORK_DIR
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

// The record rounded as the page stores it: positions to 1 cm, headings to 1 mrad, covariances
// to 4 significant digits as Float32s.
const CM = 0.005 + 1e-9, MRAD = 0.0005 + 1e-9;
const sameSignificant = (got, want) => Math.abs(got - want) <= 5e-4 * Math.abs(want) + 1e-12;

async function main() {
  fs.mkdirSync(work, { recursive: true });
  const runDir = path.join(work, "probe"), fine = path.join(work, "probe_fine");
  canopyRun(["run", path.join(source, "tests/replay/data/replay_probe.json"), "--out", runDir, "--html"]);
  const run = expect.readRun(runDir), A = run.config.uavs.length, T = run.config.targets.length;

  const browser = new Browser(chromium);
  try {
    const page = await Page.open(browser, 1280, 900);
    await page.navigate("file://" + path.resolve(runDir, "replay.html"));
    await page.evaluate("CanopyReplay.ready");

    await check("the start view fits what the run covers: inside the map, filling its width or its height", async () => {
      // What the run covers: every recorded position of an agent or a person, and about them the
      // largest footprint's reach (a rectangle's half diagonal, a sector's range) as far as it
      // lies in the area of interest.
      let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
      run.record.forEach((line) => line.uavs.map((u) => u.p).concat(line.targets.map((t) => t.p)).forEach((p) => {
        x0 = Math.min(x0, p[0]); y0 = Math.min(y0, p[1]); x1 = Math.max(x1, p[0]); y1 = Math.max(y1, p[1]);
      }));
      const reach = Math.max(...run.config.uavs.map((u) => u.fov.size ? Math.hypot(u.fov.size[0], u.fov.size[1]) / 2 : u.fov.range));
      const aoi = run.config.aoi;
      const box = [Math.min(x0, Math.max(x0 - reach, aoi[0])), Math.min(y0, Math.max(y0 - reach, aoi[1])),
        Math.max(x1, Math.min(x1 + reach, aoi[2])), Math.max(y1, Math.min(y1 + reach, aoi[3]))];
      const v = await page.evaluate(`(() => { const v = CanopyReplay.app.view;
        return { a: v.toScreen(${box[0]}, ${box[3]}), b: v.toScreen(${box[2]}, ${box[1]}), w: v.width, h: v.height }; })()`);
      const inside = v.a.x >= 0 && v.a.y >= 0 && v.b.x <= v.w && v.b.y <= v.h;
      const fill = Math.max((v.b.x - v.a.x) / v.w, (v.b.y - v.a.y) / v.h);
      console.log(`    what the run covers fills ${(100 * fill).toFixed(1)} % of the map's width or height`);
      assert(inside && fill >= 0.85, "what the run covers on the screen: " + JSON.stringify(v));
    });

    await check("the typed columns hold every pose, position and track of the record", async () => {
      const encoding = await page.evaluate("document.getElementById('replay-data').dataset.encoding");
      assert(encoding === "columns-gzip-base64", "the data's encoding: " + encoding);
      const got = await page.evaluate(`(() => { const r = CanopyReplay.app.run, out = [];
        for (let k = 0; k < r.steps; k++) out.push({
          uavs: r.agents.map((a, i) => r.uav(k, i)), targets: r.targets.map((t, n) => r.target(k, n)),
          tracks: r.agents.map((a, i) => r.tracksAt(k, i)), of: r.agents.map((a, i) => Array.from(r.trackOfTargetAt(k, i))) });
        return out; })()`);
      assert(got.length === run.record.length, got.length + " steps on the page, " + run.record.length + " recorded");
      let tracks = 0, associated = 0;
      run.record.forEach((line, k) => {
        line.uavs.forEach((u, i) => {
          const p = got[k].uavs[i];
          assert(Math.abs(p.x - u.p[0]) <= CM && Math.abs(p.y - u.p[1]) <= CM && Math.abs(p.yaw - u.yaw) <= MRAD,
            `k=${k} agent ${i}: (${p.x}, ${p.y}, ${p.yaw}), recorded (${u.p}, ${u.yaw})`);
        });
        line.targets.forEach((t, n) => {
          const p = got[k].targets[n];
          assert(Math.abs(p.x - t.p[0]) <= CM && Math.abs(p.y - t.p[1]) <= CM, `k=${k} person ${n}: (${p.x}, ${p.y}), recorded ${t.p}`);
        });
        line.agents.forEach((agent, a) => {
          const list = got[k].tracks[a];
          assert(list.length === agent.tracks.length, `k=${k} agent ${a}: ${list.length} tracks, ${agent.tracks.length} recorded`);
          agent.tracks.forEach((want, j) => {
            const t = list[j];
            assert(t.key === want.key.join(":") && t.label === want.label, `k=${k} agent ${a} track ${j}: ${t.key} ${t.label}`);
            ["x", "y", "vx", "vy"].forEach((f, n) => assert(Math.abs(t[f] - want.x[n]) <= CM, `k=${k} track ${t.key}: ${f} ${t[f]}, recorded ${want.x[n]}`));
            // The position block of P, packed row by row: P00 = P[0], P01 = P[1], P11 = P[4].
            assert(sameSignificant(t.pxx, want.P[0]) && sameSignificant(t.pxy, want.P[1]) && sameSignificant(t.pyy, want.P[4]),
              `k=${k} track ${t.key}: P (${t.pxx}, ${t.pxy}, ${t.pyy}), recorded (${want.P[0]}, ${want.P[1]}, ${want.P[4]})`);
            tracks++;
          });
          for (let n = 0; n < T; n++) {
            const want = expect.trackOf(run, k, a, n), j = got[k].of[a][n];
            assert(want ? agent.tracks[j] === want : j === -1, `k=${k} agent ${a} person ${n}: track ${j}`);
            if (want) associated++;
          }
        });
      });
      assert(tracks > 0 && associated > 0, `${tracks} tracks, ${associated} associated: the run tests nothing`);
    });

    await check("the plans are copied while unchanged, drawn again when they change, as drawn directly", async () => {
      // Steps where no plan was made and every planned path is the step before's copy the
      // plans' cache; a plan line redraws it.
      const r = await page.evaluate(`(() => { const app = CanopyReplay.app, out = [];
        CanopyReplay.LAYERS.forEach((l) => app.setLayer(l.id, true));
        app.setAgent(0);
        for (let k = 0; k < app.run.steps; k++) {
          const before = app.slow.stats.renders;
          app.setStep(k);
          out.push(app.slow.stats.renders - before);
        }
        return out; })()`);
      const same = (x, y) => JSON.stringify(x) === JSON.stringify(y);
      let copied = 0, redrawn = 0;
      for (let k = 1; k < r.length; k++) {
        const line = run.record[k], prev = run.record[k - 1];
        const plansSame = !line.plan && line.agents.every((a, i) => same(a.planned_path, prev.agents[i].planned_path));
        if (line.plan) {
          assert(r[k] === 1, `k=${k}: a plan was made and the cache was not drawn again`);
          redrawn++;
        }
        if (plansSame) {
          assert(r[k] === 0, `k=${k}: nothing changed and the cache was drawn again`);
          copied++;
        }
      }
      assert(copied > 10 && redrawn > 3, `${copied} steps copied, ${redrawn} redrawn: the run tests nothing`);
      // The same pixels as the layers drawn directly, every layer on (the cache composites
      // anti-aliased edges once more: a channel may differ by a few levels).
      let worst = 0, differ = 0;
      for (const k of [13, 37, 52]) {
        await page.evaluate(`CanopyReplay.app.setStep(${k})`);
        const cached = await mapPixels(page);
        await page.evaluate("(() => { const app = CanopyReplay.app; CanopyReplay.drawMap(app.ctx, app.view, app.run, app.state, app.backdrop); })()");
        const direct = await mapPixels(page);
        for (let o = 0; o < direct.data.length; o++) {
          const d = Math.abs(direct.data[o] - cached.data[o]);
          worst = Math.max(worst, d);
          if (d > 0) differ++;
        }
      }
      console.log(`    cached against direct: ${differ} channel values differ, by ${worst} at most`);
      assert(worst <= 3, `a channel differs by ${worst} levels`);
    });

    await check("a crowd (more people on the map than CROWD) is drawn as squares without names", async () => {
      // The probe has four people; CROWD set to 2 makes them a crowd, 64 (the page's) not.
      // The names are counted with every layer on; the pixels read with the people alone (the
      // agents' darts and names left out for that draw).
      const probe = (crowd) => page.evaluate(`(() => { const app = CanopyReplay.app, R = CanopyReplay, k = 20;
        R.CROWD = ${crowd}; app.setStep(k);
        let names = 0; const own = R.label; R.label = function () { names++; return own.apply(null, arguments); };
        app.draw(); R.label = own;
        const keep = [R.drawAgents, R.drawNames];
        R.drawAgents = R.drawNames = function () {};
        R.LAYERS.forEach((l) => { app.state.layers[l.id] = l.id === "truth"; });
        app.draw();
        [R.drawAgents, R.drawNames] = keep;
        R.LAYERS.forEach((l) => { app.state.layers[l.id] = true; });
        const d = app.ctx.getImageData(0, 0, app.view.canvas.width, app.view.canvas.height), W = d.width;
        const px = (x, y) => Array.from(d.data.subarray(4 * (y * W + x), 4 * (y * W + x) + 3));
        return { names, people: app.run.targets.map((t, n) => { const q = app.run.target(k, n), s = app.view.toScreen(q.x, q.y);
          const x = Math.round(s.x), y = Math.round(s.y);  // whole pixels (ratio 1)
          return { centre: px(x, y), corner: px(x + 4, y + 4) }; }) }; })()`);
      const crowd = await probe(2), few = await probe(64);
      await page.evaluate("CanopyReplay.CROWD = 64; CanopyReplay.app.draw()");
      const black = (c) => c.every((v) => v <= 40), white = (c) => c.every((v) => v >= 235);
      // Square: black to 4 px from the centre, its 1 px rim white; the disc (radius 5 and a white
      // edge) leaves the corner at (4, 4), 5.7 px out, to what lies under it.
      const squares = crowd.people.filter((p) => black(p.centre) && white(p.corner)).length;
      const discs = few.people.filter((p) => black(p.centre) && !white(p.corner)).length;
      assert(squares >= T - 1, `${squares} of ${T} people drawn as squares: ${JSON.stringify(crowd.people)}`);
      assert(discs >= T - 1, `${discs} of ${T} people drawn as discs: ${JSON.stringify(few.people)}`);
      assert(crowd.names === A && few.names > A, `names drawn: ${crowd.names} in a crowd, ${few.names} without (${A} agents)`);
    });

    await check("view A B --overlay: B drawn over A at its step of the same time, one page, offline, in the link", async () => {
      // The probe at dt 0.1 s over the probe at dt 0.2 s: one time is a different step in each.
      canopyRun(["run", path.join(source, "tests/replay/data/replay_probe.json"), "--set", "clock.dt=0.1", "--set", "seed=8", "--out", fine]);
      const out = path.join(work, "overlay.html");
      canopyRun(["view", runDir, fine, "--overlay", "--out", out]);
      const b = expect.readRun(fine);
      const tab = await Page.open(browser, 1280, 900);
      await tab.navigate("file://" + path.resolve(out));
      await tab.evaluate("CanopyReplay.ready");
      const k = 30, kB = Math.min(b.record.length - 1, Math.round(k * run.config.clock.dt / b.config.clock.dt));
      const got = await tab.evaluate(`(() => { const app = CanopyReplay.app; app.setStep(${k});
        return { kB: CanopyReplay.secondStep(app.run, app.state.second.run, ${k}), clock: document.getElementById("clock").textContent }; })()`);
      assert(got.kB === kB && got.clock.indexOf("over it k = " + kB) >= 0, `B at step ${got.kB} (${got.clock}), want ${kB}`);
      // Each of B's agents: its hollow dart's outline (its colour, 2.5 px) passes 9 px ahead of
      // its recorded position, the dart's tip; with B hidden (the key o) that pixel changes.
      const on = await mapPixels(tab);
      await tab.key("o", "KeyO", 79);
      const hidden = await tab.evaluate("CanopyReplay.app.state.second.on");
      const off = await mapPixels(tab);
      let changed = 0;
      for (let i = 0; i < A; i++) {
        const u = b.record[kB].uavs[i];
        const s = await tab.evaluate(`(() => { const v = CanopyReplay.app.view, p = v.toScreen(${u.p[0]}, ${u.p[1]});
          return { x: Math.floor((p.x + 8 * Math.cos(${u.yaw})) * v.ratio), y: Math.floor((p.y - 8 * Math.sin(${u.yaw})) * v.ratio) }; })()`);
        const o = 4 * (s.y * on.w + s.x);
        if (on.data[o] !== off.data[o] || on.data[o + 1] !== off.data[o + 1] || on.data[o + 2] !== off.data[o + 2]) changed++;
      }
      assert(hidden === false, "the key o did not hide the second run");
      // The address says so (second=0), and a page opened with it starts with B hidden.
      let hash = "";
      for (let waited = 0; waited < 10000 && hash.indexOf("second=0") < 0; waited += 50) {
        hash = await tab.evaluate("location.hash");
        await new Promise((r) => setTimeout(r, 50));
      }
      const again = await Page.open(browser, 1280, 900);
      await again.navigate("file://" + path.resolve(out) + hash);
      const restored = await again.evaluate(`CanopyReplay.ready.then(() => ({ on: CanopyReplay.app.state.second.on,
        box: document.getElementById("second-on").checked, k: CanopyReplay.app.state.k }))`);
      assert(hash.indexOf("second=0") >= 0 && restored.on === false && restored.box === false && restored.k === k,
        `the fragment ${hash} restored ${JSON.stringify(restored)}`);
      await again.send("Page.close").catch(() => {});
      assert(changed >= A - 1, `${changed} of ${A} of B's darts changed their pixels when hidden`);
      // Its people's rings: the pixel 5 px right of each recorded position is the rings' colour.
      const ring = await tab.evaluate("CanopyReplay.SECOND_RUN_RING");
      const want = ring.match(/\d+/g).map(Number);
      let rings = 0;
      for (const t of b.record[kB].targets) {
        const s = await tab.evaluate(`CanopyReplay.app.view.toPixel(${t.p[0]}, ${t.p[1]})`);
        const o = 4 * (s.y * on.w + s.x + 5);
        if ([0, 1, 2].every((c) => Math.abs(on.data[o + c] - want[c]) <= 40)) rings++;
      }
      assert(rings >= b.record[kB].targets.length - 1, `${rings} of B's people show a ring`);
      assert(tab.errors.length === 0, tab.errors.join("\n"));
      const outside = tab.requests.filter((u) => u !== "file://" + path.resolve(out) && !u.startsWith("data:"));
      assert(outside.length === 0 && tab.failed.length === 0, "requests beyond the page: " + outside.join(", "));
    });
    await check("altitudes (issue 53): the record's z at every step, the footprint at it, a label and a plot", async () => {
      const none = await page.evaluate("CanopyReplay.app.run.altitude === null");
      assert(none, "a run without altitudes has an altitude column");
      const high = path.join(work, "altitude");
      canopyRun(["run", "altitude_tradeoff", "--set", "clock.duration=8", "--out", high, "--html"]);
      const rec = expect.readRun(high);
      const tab = await Page.open(browser, 1280, 900);
      await tab.navigate("file://" + path.resolve(high, "replay.html"));
      await tab.evaluate("CanopyReplay.ready");
      const got = await tab.evaluate(`(() => { const r = CanopyReplay.app.run, out = [];
        for (let k = 0; k < r.steps; k++) out.push(r.agents.map((a, i) => ({ z: r.altitude(k, i),
          size: CanopyReplay.footprintAt(r, k, i).size, text: CanopyReplay.altitudeText(r, k, i) })));
        return { steps: out, fields: CanopyReplay.plotFields(r, { kind: "agent", index: 0 }, 0).map((f) => f.id),
          plotted: Array.from(CanopyReplay.plotFields(r, { kind: "agent", index: 0 }, 0).pop().values()) }; })()`);
      let moved = 0;
      rec.record.forEach((line, k) => line.uavs.forEach((u, i) => {
        const g = got.steps[k][i];
        assert(Math.abs(g.z - u.z) <= CM, `k=${k} agent ${i}: z ${g.z}, recorded ${u.z}`);
        // 16 x 12 m at 20 m: the footprint at z is 16 z/20 x 12 z/20 (the record's to 1 cm).
        assert(Math.abs(g.size[0] - 16 * u.z / 20) <= 0.01 && Math.abs(g.size[1] - 12 * u.z / 20) <= 0.01,
          `k=${k} agent ${i}: footprint ${g.size} at z ${u.z}`);
        assert(g.text === " " + Math.round(g.z) + " m", `k=${k} agent ${i}: label "${g.text}"`);
        if (Math.abs(u.z - 20) > 0.5) moved++;
      }));
      assert(moved > 0, "no UAV changed altitude: the check tests nothing");
      assert(got.fields[got.fields.length - 1] === "altitude", "the timeline's fields: " + got.fields);
      assert(got.plotted.every((z, k) => Math.abs(z - rec.record[k].uavs[0].z) <= CM), "the plotted altitude");
      assert(tab.errors.length === 0, tab.errors.join("\n"));
      await tab.send("Page.close").catch(() => {});
    });
    assert(page.errors.length === 0, page.errors.join("\n"));
  } finally {
    await browser.close();
  }
  finish();
}

main().catch(crashed);
