// The replay page's inspecting and sharing in Debian's headless chromium, checked against the
// run's own files: the hover readout, an agent's and a person's numbers at a step, the fields
// plotted over time, the URL fragment, the PNG and SVG exports, and the linked views of two runs
// side by side. Usage: node inspect_test.js CANOPY_BINARY SOURCE_DIR WORK_DIR
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

const near = (a, b, tol) => Math.abs(a - b) <= tol;

// The page's address fragment once it holds `part` (the page writes it 150 ms after the last
// change; a loaded machine may take longer), or what it holds after 10 s.
async function fragmentHolding(page, part) {
  for (let waited = 0; waited < 10000; waited += 50) {
    const hash = await page.evaluate("location.hash");
    if (hash.indexOf(part) >= 0) return hash;
    await new Promise((r) => setTimeout(r, 50));
  }
  return page.evaluate("location.hash");
}

// The plan line in force at step k (the last line at or before k that planned), or null.
function planLine(run, k) {
  for (let h = k; h >= 0; h--) if (run.record[h].plan) return run.record[h];
  return null;
}

// What agent a held of each teammate at step k's epoch, from the record, as the intentions test
// of browser_test.js derives it: "j:epoch:status" in teammate order ("ok", "lost" or "none";
// the probe has no latency and no range).
function heldAt(run, k, a) {
  const line = planLine(run, k);
  if (!line) return [];
  let previous = -1;
  for (let h = line.k - 1; h >= 0; h--) if (run.record[h].plan) { previous = run.record[h].plan.epoch; break; }
  const order = line.plan.messages.map((m) => m.from), part = line.plan.agents.find((p) => p.agent === a);
  const out = [];
  for (let j = 0; j < run.config.uavs.length; j++) {
    if (j === a || order.indexOf(j) < 0) continue;
    const expected = order.indexOf(j) < order.indexOf(a) ? line.plan.epoch : previous;
    const held = part.joint_epoch[j];
    const status = expected >= 0 && held < expected ? "lost" : held < 0 && expected < 0 ? "none" : "ok";
    out.push(run.config.uavs[j].name + ":" + held + ":" + status);
  }
  return out;
}

async function main() {
  fs.mkdirSync(work, { recursive: true });
  const runDir = path.join(work, "probe");
  canopyRun(["run", path.join(source, "tests/replay/data/replay_probe.json"), "--out", runDir, "--html"]);
  const run = expect.readRun(runDir), names = run.config.uavs.map((u) => u.name);
  const url = "file://" + path.resolve(runDir, "replay.html");
  const browser = new Browser(chromium);
  try {
    const page = await Page.open(browser, 1280, 900);
    await page.navigate(url);
    const rect = await page.evaluate(`(() => { const r = document.getElementById("map").getBoundingClientRect();
      return { x: r.left, y: r.top, w: r.width, h: r.height }; })()`);

    await check("hover: the point under the cursor, the nearest agent, person and track, the track's mean and covariance", async () => {
      const k = 30, a = 1;
      await page.evaluate(`CanopyReplay.app.setAgent(${a}); CanopyReplay.app.setStep(${k})`);
      const line = run.record[k];
      for (const [fx, fy] of [[0.3, 0.4], [0.55, 0.5], [0.7, 0.62]]) {
        const px = Math.round(rect.x + rect.w * fx), py = Math.round(rect.y + rect.h * fy);
        await page.send("Input.dispatchMouseEvent", { type: "mouseMoved", x: px, y: py });
        const got = await page.evaluate(`Object.assign({ hidden: document.getElementById("hover").hidden },
          document.getElementById("hover").dataset)`);
        assert(!got.hidden, "no readout under the cursor");
        // The world point from the view's centre and scale (y up in the world, down on the canvas).
        const v = await page.evaluate("(({ cx, cy, scale, width, height }) => ({ cx, cy, scale, width, height }))(CanopyReplay.app.view)");
        const x = v.cx + (px - rect.x - v.width / 2) / v.scale, y = v.cy - (py - rect.y - v.height / 2) / v.scale;
        assert(near(+got.x, x, 1e-6) && near(+got.y, y, 1e-6), `readout at (${got.x}, ${got.y}), the cursor at (${x}, ${y})`);
        const nearest = (list) => list.reduce((best, q, n) => {
          const d = Math.hypot(q[0] - x, q[1] - y);
          return !best || d < best.d ? { n, d } : best;
        }, null);
        const ag = nearest(line.uavs.map((u) => u.p)), pe = nearest(line.targets.map((t) => t.p));
        const [agName, agD] = got.agent.split(":"), [peName, peD] = got.person.split(":");
        assert(agName === names[ag.n] && near(+agD, ag.d, 0.02), `nearest agent ${got.agent}, the record's ${names[ag.n]} at ${ag.d}`);
        assert(peName === run.config.targets[pe.n].name && near(+peD, pe.d, 0.02), `nearest person ${got.person}, the record's at ${pe.d}`);
        // The nearest of agent a's tracks, its distance and its Mahalanobis distance under the
        // position block of P (P packed row by row: P00 = P[0], P01 = P[1], P11 = P[4]).
        const tracks = line.agents[a].tracks, tr = tracks[nearest(tracks.map((t) => t.x)).n];
        const dx = x - tr.x[0], dy = y - tr.x[1], [p00, p01, p11] = [tr.P[0], tr.P[1], tr.P[4]];
        const inv = [p11, -p01, p00].map((q) => q / (p00 * p11 - p01 * p01));
        const m = Math.sqrt(dx * (inv[0] * dx + inv[1] * dy) + dy * (inv[1] * dx + inv[2] * dy));
        const [key, d, mahalanobis] = got.track.split(":").reduce((acc, part, n, all) =>
          n === 0 ? [all.slice(0, all.length - 2).join(":")] : n >= all.length - 2 ? acc.concat([+part]) : acc, []);
        assert(key === tr.key.join(":"), `nearest track ${key}, the record's ${tr.key}`);
        assert(near(d, Math.hypot(dx, dy), 0.02) && near(mahalanobis, m, 0.01 * m + 0.01),
          `track at ${d} m, ${mahalanobis} sigma; the record: ${Math.hypot(dx, dy)} m, ${m} sigma`);
      }
      await page.send("Input.dispatchMouseEvent", { type: "mouseMoved", x: 5, y: 5 });
      assert(await page.evaluate("document.getElementById('hover').hidden"), "the readout stays after the cursor left the map");
    });

    await check("click an agent: its plan and cost, messages sent, plans held and tracks at this step are the record's", async () => {
      let tested = 0;
      for (const k of [12, 31, 47]) {
        await page.evaluate(`CanopyReplay.app.setStep(${k})`);
        for (let i = 0; i < names.length; i++) {
          const p = run.record[k].uavs[i].p, s = await page.evaluate(`CanopyReplay.app.view.toScreen(${p[0]}, ${p[1]})`);
          // Only an agent no other one stands within 14 px of (a click there is its own).
          let clear = true;
          for (let j = 0; j < names.length; j++) {
            const q = run.record[k].uavs[j].p, t = await page.evaluate(`CanopyReplay.app.view.toScreen(${q[0]}, ${q[1]})`);
            if (j !== i && Math.hypot(t.x - s.x, t.y - s.y) < 14) clear = false;
          }
          if (!clear) continue;
          await page.click(rect.x + s.x, rect.y + s.y);
          const got = await page.evaluate("Object.assign({}, document.getElementById('numbers').dataset)");
          const line = planLine(run, k), part = line && line.plan.agents.find((q) => q.agent === i);
          assert(got.kind === "agent", `k=${k}: a click on ${names[i]} shows ${got.kind}`);
          // The page carries 4 significant digits (replay/packed_json.h, kSignificantDigits).
          assert(part ? near(+got.cost, part.cost, 5e-4 * Math.abs(part.cost) + 1e-9) : got.cost === "",
            `k=${k} ${names[i]}: cost ${got.cost}, the record's ${part && part.cost}`);
          const sent = line ? line.plan.messages.filter((m) => m.from === i).length : 0;
          assert(+got.sent === sent, `k=${k} ${names[i]}: ${got.sent} messages sent, the record ${sent}`);
          assert(+got.tracks === run.record[k].agents[i].tracks.length, `k=${k} ${names[i]}: ${got.tracks} tracks`);
          assert(got.held === heldAt(run, k, i).join(","), `k=${k} ${names[i]}: held ${got.held}, the record ${heldAt(run, k, i)}`);
          tested++;
        }
      }
      assert(tested >= 8, "only " + tested + " agents clear to click");
    });

    await check("plots: each field of an agent and of a person over the run is the record's", async () => {
      const K = run.record.length, i = 2, t = 1, a = 0;
      await page.evaluate(`CanopyReplay.app.select({ kind: "agent", index: ${i} })`);
      const series = async (id) => page.evaluate(`(() => { CanopyReplay.app.setPlot("${id}");
        return { plot: CanopyReplay.app.series.plot, values: Array.from(CanopyReplay.app.series.trace),
          option: document.getElementById("plot-field").value }; })()`);
      const want = {
        tracks: (k) => run.record[k].agents[i].tracks.length,
        trace: (k) => run.record[k].agents[i].tracks.reduce((s, tr) => s + tr.P[0] + tr.P[4], 0),
        cost: (k) => { const l = planLine(run, k); return l ? l.plan.agents.find((q) => q.agent === i).cost : NaN; },
        sent: (k) => { const l = planLine(run, k); return l ? l.plan.messages.filter((m) => m.from === i).length : NaN; },
        received: (k) => heldAt(run, k, i).filter((h) => h.endsWith(":ok")).length,
        missed: (k) => heldAt(run, k, i).filter((h) => !h.endsWith(":ok")).length,
        ospa: (k) => run.summary.uavs[i].ospa_m[k]
      };
      for (const id of Object.keys(want)) {
        const got = await series(id);
        assert(got.plot === id && got.option === id && got.values.length === K, `${id}: plotted ${got.plot} (${got.values.length} values)`);
        for (let k = 0; k < K; k++) {
          const w = want[id](k), g = got.values[k];
          assert(Number.isNaN(w) ? g === null || Number.isNaN(g) : near(g, w, 2e-3 * Math.abs(w) + 1e-6), `${id} at k=${k}: ${g}, the record ${w}`);
        }
      }
      await page.evaluate(`CanopyReplay.app.setAgent(${a}); CanopyReplay.app.select({ kind: "target", index: ${t} })`);
      const person = {
        error: (k) => { const tr = expect.trackOf(run, k, a, t), p = run.record[k].targets[t].p; return tr ? Math.hypot(tr.x[0] - p[0], tr.x[1] - p[1]) : NaN; },
        seen: (k) => run.record[k].scans.filter((s) => s.visible.indexOf(t) >= 0).length
      };
      for (const id of Object.keys(person)) {
        const got = await series(id);
        for (let k = 0; k < K; k++) {
          const w = person[id](k), g = got.values[k];
          assert(Number.isNaN(w) ? g === null : near(g, w, 0.02), `person ${id} at k=${k}: ${g}, the record ${w}`);
        }
      }
      // The person's numbers beside the map: the shown agent's track of it and its error.
      for (const k of [5, 33, K - 1]) {
        await page.evaluate(`CanopyReplay.app.setStep(${k})`);
        const got = await page.evaluate("Object.assign({}, document.getElementById('numbers').dataset)");
        const w = person.error(k);
        assert(got.kind === "target" && (Number.isNaN(w) ? got.error === "" : near(+got.error, w, 0.02)),
          `person's numbers at k=${k}: error ${got.error}, the record ${w}`);
      }
    });

    await check("the URL fragment holds step, layers, view, beliefs, selection and plot; opening it restores them", async () => {
      await page.evaluate(`(() => { const app = CanopyReplay.app;
        app.setAgent(2); app.select({ kind: "target", index: 3 }); app.setPlot("error");
        app.setLayer("links", false); app.setLayer("map", false);
        app.view.zoom(2.5, 200, 150); app.view.pan(-30, 20); app.setStep(41); })()`);
      const hash = await fragmentHolding(page, "k=41&");
      const fields = new URLSearchParams(hash.slice(1));
      assert(fields.get("k") === "41" && fields.get("agent") === "2" && fields.get("sel") === "t3" && fields.get("plot") === "error" &&
        fields.get("layers") === "trees,truth,sensors,tracks,plans", "fragment " + hash);
      const state = "(({ state: s, view: v }) => ({ k: s.k, agent: s.agent, sel: s.selection, layers: s.layers, plot: s.plot, " +
        "view: [v.cx, v.cy, v.scale] }))(CanopyReplay.app)";
      const before = await page.evaluate(state), pixels = await mapPixels(page);
      const tab = await Page.open(browser, 1280, 900);
      await tab.navigate(url + hash);
      const after = await tab.evaluate(state);
      ["k", "agent", "sel", "layers", "plot"].forEach((key) => assert(JSON.stringify(after[key]) === JSON.stringify(before[key]),
        `${key}: opened ${JSON.stringify(after[key])}, shared ${JSON.stringify(before[key])}`));
      after.view.forEach((v, n) => assert(near(v, before.view[n], 1e-9 * Math.abs(before.view[n]) + 1e-9), "view " + after.view + " vs " + before.view));
      const again = await mapPixels(tab);
      let differ = 0;
      for (let o = 0; o < again.data.length; o++) if (again.data[o] !== pixels.data[o]) differ++;
      assert(again.w === pixels.w && differ === 0, differ + " bytes of the map differ between the page and its link");
      const checked = await tab.evaluate("CanopyReplay.LAYERS.map((l) => document.getElementById('layer-' + l.id).checked)");
      assert(JSON.stringify(checked) === JSON.stringify([true, true, true, true, false, true, false]), "switches " + checked);
      assert(tab.errors.length === 0, tab.errors.join("\n"));
      await tab.send("Page.close").catch(() => {});
    });

    await check("PNG export: the map's own pixels", async () => {
      const r = await page.evaluate(`new Promise((done) => {
        const url = CanopyReplay.exportPng(CanopyReplay.app), image = new Image();
        image.onload = () => {
          const c = document.createElement("canvas"), m = document.getElementById("map");
          c.width = image.width; c.height = image.height;
          const ctx = c.getContext("2d");
          ctx.drawImage(image, 0, 0);
          const a = ctx.getImageData(0, 0, c.width, c.height).data, b = m.getContext("2d").getImageData(0, 0, m.width, m.height).data;
          let differ = 0;
          for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) differ++;
          done({ head: url.slice(0, 22), w: image.width, h: image.height, mw: m.width, mh: m.height, differ });
        };
        image.src = url;
      })`);
      assert(r.head === "data:image/png;base64,", "not a PNG: " + r.head);
      assert(r.w === r.mw && r.h === r.mh && r.differ === 0, JSON.stringify(r));
    });

    await check("SVG export: the same view as shapes and text, its agents where the record puts them", async () => {
      const k = 20;
      await page.evaluate(`(() => { const app = CanopyReplay.app; CanopyReplay.LAYERS.forEach((l) => app.setLayer(l.id, true));
        app.fit(); app.setStep(${k}); })()`);
      const r = await page.evaluate(`new Promise((done) => {
        const app = CanopyReplay.app, svg = CanopyReplay.exportSvg(app);
        const doc = new DOMParser().parseFromString(svg, "image/svg+xml");
        const texts = Array.from(doc.querySelectorAll("text")).map((t) => t.textContent);
        const image = new Image();
        image.onload = () => {
          const c = document.createElement("canvas"), m = document.getElementById("map");
          c.width = m.width; c.height = m.height;
          const ctx = c.getContext("2d");
          ctx.drawImage(image, 0, 0, c.width, c.height);
          const a = ctx.getImageData(0, 0, c.width, c.height).data, b = m.getContext("2d").getImageData(0, 0, m.width, m.height).data;
          let close = 0;
          for (let i = 0; i < a.length; i += 4) {
            if (Math.hypot(a[i] - b[i], a[i + 1] - b[i + 1], a[i + 2] - b[i + 2]) <= 48) close++;
          }
          window.svgRaster = c;
          done({ errors: doc.getElementsByTagName("parsererror").length, paths: doc.querySelectorAll("path").length,
            images: doc.querySelectorAll("image").length, texts, close: close / (a.length / 4) });
        };
        image.src = "data:image/svg+xml;base64," + btoa(unescape(encodeURIComponent(svg)));
      })`);
      assert(r.errors === 0 && r.paths > 20 && r.images === 0, "an SVG of " + JSON.stringify(r).slice(0, 300));
      assert(r.texts.some((t) => t.indexOf("t = 4.00 s") >= 0), "no clock text at k=20: " + r.texts.slice(0, 5));
      assert(names.filter((n) => r.texts.indexOf(n) >= 0).length >= 3, "agent names in the SVG: " + r.texts);
      assert(r.close >= 0.97, "only " + r.close + " of the SVG's pixels are close to the map's");
      const img = await mapPixels(page, "window.svgRaster");
      let checked = 0;
      const pixels = [];
      for (const uav of run.record[k].uavs) pixels.push(await page.evaluate(`CanopyReplay.app.view.toPixel(${uav.p[0]}, ${uav.p[1]})`));
      pixels.forEach((px, i) => {
        if (pixels.some((q, j) => j > i && Math.hypot(q.x - px.x, q.y - px.y) < 12)) return;
        const o = 4 * (px.y * img.w + px.x), want = expect.PALETTE[i % 8], got = [img.data[o], img.data[o + 1], img.data[o + 2]];
        assert(got.every((v, c) => Math.abs(v - want[c]) <= 2), `${names[i]} at (${px.x}, ${px.y}) in the SVG: ${got}, want ${want}`);
        checked++;
      });
      assert(checked >= 3, "only " + checked + " agents checked");
      assert(page.errors.length === 0, page.errors.join("\n"));
    });

    await check("side by side: a zoom or a drag in one page moves the other's view with it; a link keeps time and view", async () => {
      const b = path.join(work, "probe_fine"), out = path.join(work, "side_by_side.html");
      canopyRun(["run", path.join(source, "tests/replay/data/replay_probe.json"), "--set", "clock.dt=0.1",
        "--set", "uavs.0.start=[-35,25]", "--out", b]);
      canopyRun(["view", runDir, b, "--out", out]);
      const tab = await Page.open(browser, 1600, 900);
      await tab.navigate("file://" + path.resolve(out));
      await tab.evaluate("CanopySideBySide.ready.then(() => true)");
      const views = () => tab.evaluate("CanopySideBySide.apps.map((a) => [a.view.cx, a.view.cy, a.view.scale])");
      const same = (v) => v[0].every((x, n) => x === v[1][n]);
      const opened = await views();
      assert(same(opened), "the two pages open on different views: " + JSON.stringify(opened));
      // Both runs' boxes are shown whole.
      const boxes = await tab.evaluate(`CanopySideBySide.apps.map((a) => { const v = a.view, lo = v.toWorld(0, v.height), hi = v.toWorld(v.width, 0);
        return [lo.x, lo.y, hi.x, hi.y]; })`);
      for (const dir of [runDir, b]) {
        for (const line of expect.readRun(dir).record) {
          for (const u of line.uavs) {
            assert(boxes.every((bx) => u.p[0] >= bx[0] && u.p[0] <= bx[2] && u.p[1] >= bx[1] && u.p[1] <= bx[3]),
              `${dir}: an agent at ${u.p} outside the shown ${JSON.stringify(boxes)}`);
          }
        }
      }
      // A wheel over the left page's map and a drag over the right one's, as a user does.
      const frame = async (id) => tab.evaluate(`(() => { const f = document.getElementById("${id}").getBoundingClientRect(),
        m = document.getElementById("${id}").contentDocument.getElementById("map").getBoundingClientRect();
        return { x: f.left + m.left + m.width / 2, y: f.top + m.top + m.height / 2 }; })()`);
      const left = await frame("run-a"), right = await frame("run-b");
      await tab.wheel(Math.round(left.x), Math.round(left.y), -300);
      const zoomed = await views();
      assert(zoomed[0][2] > 1.3 * opened[0][2] && same(zoomed), "after a wheel on the left: " + JSON.stringify(zoomed));
      await tab.drag(Math.round(right.x), Math.round(right.y), Math.round(right.x) - 60, Math.round(right.y) + 30);
      const dragged = await views();
      assert(dragged[1][0] !== zoomed[1][0] && same(dragged), "after a drag on the right: " + JSON.stringify(dragged));
      // The address holds the time and the view: a link opens both pages at the same steps and views.
      await tab.evaluate(`(() => { const s = document.getElementById("clock-slider"); s.value = "5.1"; s.dispatchEvent(new Event("input")); })()`);
      const hash = await fragmentHolding(tab, "t=5.1&"), steps = () => "CanopySideBySide.apps.map((a) => a.state.k)";
      const before = { steps: await tab.evaluate(steps()), views: await views() };
      const link = await Page.open(browser, 1600, 900);
      await link.navigate("file://" + path.resolve(out) + hash);
      await link.evaluate("CanopySideBySide.ready.then(() => true)");
      const after = { steps: await link.evaluate(steps()),
        views: await link.evaluate("CanopySideBySide.apps.map((a) => [a.view.cx, a.view.cy, a.view.scale])") };
      assert(/^#t=5\.1&view=/.test(hash) && JSON.stringify(after.steps) === JSON.stringify(before.steps) &&
        after.views.every((v, n) => v.every((x, c) => near(x, before.views[n][c], 1e-9 * Math.abs(x) + 1e-9))),
      `link ${hash}: ${JSON.stringify(after)}, shared ${JSON.stringify(before)}`);
      await link.send("Page.close").catch(() => {});
      // Unlinked, a zoom moves one page only.
      await tab.evaluate(`(() => { const box = document.getElementById("link-views"); box.checked = false;
        box.dispatchEvent(new Event("change")); })()`);
      await tab.wheel(Math.round(left.x), Math.round(left.y), -300);
      const apart = await views();
      assert(apart[0][2] > dragged[0][2] && apart[1][2] === dragged[1][2], "unlinked: " + JSON.stringify(apart));
      assert(tab.errors.length === 0, tab.errors.join("\n"));
    });

    await check("no console error after every interaction", async () => {
      assert(page.errors.length === 0, page.errors.join("\n"));
    });
  } finally {
    await browser.close();
  }
  finish();
}

main().catch(crashed);
