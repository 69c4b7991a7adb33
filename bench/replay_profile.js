// Where a replay step's time goes: the DevTools protocol's CPU profiler over 60 steps (→) of a
// written page (every layer on, a person's timeline open, from a third of the run; as
// tests/replay/step_time.js), the functions by self time, and a timing of each map layer drawn
// alone at that step (best of 9, ms, with the pixels read back).
// Usage: node bench/replay_profile.js PAGE.html [TOP]
"use strict";

const path = require("path");
const { Browser, Page } = require("../tests/replay/cdp.js");
const { prepare, pressTimes } = require("../tests/replay/step_time.js");

async function main() {
  const [pageFile, topText] = process.argv.slice(2);
  const top = +(topText || 25);
  const browser = new Browser(process.env.CANOPY_CHROMIUM);
  try {
    const tab = await Page.open(browser, 1280, 900);
    await tab.navigate("file://" + path.resolve(pageFile));
    await tab.evaluate("CanopyReplay.ready || null");
    await prepare(tab);
    await tab.send("Profiler.enable");
    await tab.send("Profiler.setSamplingInterval", { interval: 100 });
    await tab.send("Profiler.start");
    const s = await pressTimes(tab, 60);
    const { profile } = await tab.send("Profiler.stop");
    const byId = new Map(profile.nodes.map((n) => [n.id, n]));
    const self = new Map();
    const dts = profile.timeDeltas;
    profile.samples.forEach((id, i) => {
      const n = byId.get(id), f = n.callFrame;
      const key = (f.functionName || "(anonymous)") + " " + (f.url ? path.basename(f.url) : "") + ":" + f.lineNumber;
      self.set(key, (self.get(key) || 0) + (dts[i] || 0) / 1000);
    });
    const total = Array.from(self.values()).reduce((a, b) => a + b, 0);
    console.log(`median step ${s.median.toFixed(1)} ms over ${s.times.length}; profile ${total.toFixed(0)} ms`);
    Array.from(self.entries()).sort((a, b) => b[1] - a[1]).slice(0, top)
      .forEach(([k, ms]) => console.log(`${(ms / s.times.length).toFixed(2).padStart(7)} ms/step  ${k}`));
    const layers = await tab.evaluate(`(() => {
      const app = CanopyReplay.app, out = {}, ids = CanopyReplay.LAYERS.map((l) => l.id);
      function time(on) {
        ids.forEach((id) => { app.state.layers[id] = !!on[id]; });
        let best = Infinity;
        for (let r = 0; r < 9; r++) {
          const t0 = performance.now();
          CanopyReplay.drawMap(app.ctx, app.view, app.run, app.state, app.backdrop);
          app.ctx.getImageData(0, 0, 1, 1);
          best = Math.min(best, performance.now() - t0);
        }
        return +best.toFixed(2);
      }
      out.none = time({});
      ids.forEach((id) => { const on = {}; on[id] = true; out[id] = time(on); });
      const all = {}; ids.forEach((id) => { all[id] = true; });
      out.all = time(all);
      ids.forEach((id) => { app.state.layers[id] = true; });
      return out;
    })()`);
    console.log("map alone, best of 9 (ms): " + JSON.stringify(layers));
  } finally {
    await browser.close();
  }
}

main().catch((e) => { console.error(e); process.exit(1); });
