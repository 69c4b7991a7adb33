// A screenshot of a replay page in Debian's headless chromium (the README's docs/replay.png):
//   node scripts/replay_screenshot.js PAGE.html OUT.png STEP [TARGET] [ZOOM] [WIDTHxHEIGHT]
// shows step STEP with person TARGET's timeline, the map zoomed ZOOM times about its centre.
"use strict";

const fs = require("fs");
const path = require("path");
const { Browser, Page } = require("../tests/replay/cdp.js");

const [page, out, step, target, zoom, size] = process.argv.slice(2);
const [width, height] = (size || "1100x760").split("x").map(Number);

(async () => {
  const browser = new Browser(process.env.CANOPY_CHROMIUM);
  try {
    const tab = await Page.open(browser, width, height);
    await tab.navigate("file://" + path.resolve(page));
    await tab.evaluate(`(() => { const a = CanopyReplay.app;
      a.select({ kind: "target", index: ${+(target || 0)} });
      a.view.zoom(${+(zoom || 1)}, a.view.width / 2, a.view.height / 2);
      a.setStep(${+step}); })()`);
    if (tab.errors.length) throw new Error(tab.errors.join("\n"));
    fs.writeFileSync(out, await tab.screenshot());
  } finally {
    await browser.close();
  }
})().catch((e) => { console.error(e); process.exit(1); });
