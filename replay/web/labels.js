// Names on the map placed without overlap (as the PNG frames place them), and the screen-box index
// the placement and the tracks' labels use.
/* global CanopyReplay */
(function () {
  "use strict";

  const FONT = CanopyReplay.FONT;
  const widths = new Map();   // font and text → width (px)

  function overlaps(a, b) {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
  }

  // Screen boxes binned into 64 px cells, so that asking whether a box overlaps any of a few
  // hundred looks at its neighbours only.
  function Boxes() { this.cells = new Map(); }
  Boxes.prototype.each = function (b, visit) {
    for (let j = Math.floor(b.y0 / 64); j <= Math.floor(b.y1 / 64); j++) {
      for (let i = Math.floor(b.x0 / 64); i <= Math.floor(b.x1 / 64); i++) {
        if (visit(j * 65536 + i) === true) return true;  // a number: no string a cell
      }
    }
    return false;
  };
  Boxes.prototype.add = function (b) {
    const cells = this.cells;
    this.each(b, function (key) {
      if (!cells.has(key)) cells.set(key, []);
      cells.get(key).push(b);
    });
  };
  Boxes.prototype.hits = function (b) {
    const cells = this.cells;
    return this.each(b, function (key) {
      const list = cells.get(key);
      return !!list && list.some(function (o) { return overlaps(o, b); });
    });
  };

  // The width (px) of `text` in `font`, measured once (ctx.measureText in that font) and
  // remembered. The font is given, not read back: reading ctx.font costs more than measuring.
  function textWidth(ctx, text, font) {
    let known = widths.get(font);
    if (!known) widths.set(font, known = new Map());
    let w = known.get(text);
    if (w === undefined) {
      const before = ctx.font;
      ctx.font = font;
      w = ctx.measureText(text).width;
      ctx.font = before;
      known.set(text, w);
    }
    return w;
  }

  // Names of people (above right first) and agents (below right first), each at the first of
  // six places around its symbol that covers no agent's or person's symbol and no name placed
  // before it (as the frames place them, render/scene_builder.cpp); where none of the six is
  // free the name is left out (the frames put it at the first place), so a crowd seen from far
  // shows the names that fit instead of a pile.
  // A crowd (more than CanopyReplay.CROWD people on the map) shows no people's names: only
  // their symbols keep the agents' names off them.
  function drawNames(ctx, view, run, k, truth) {
    const font = "bold " + FONT, crowd = CanopyReplay.peopleOnMap(view, run, k) > CanopyReplay.CROWD;
    ctx.font = font;
    ctx.lineJoin = "round";
    const symbols = new Boxes(), placed = new Boxes(), items = [];
    run.agents.forEach(function (agent, i) {
      const p = run.uav(k, i), s = view.toScreen(p.x, p.y);
      symbols.add({ x0: s.x - 10, y0: s.y - 10, x1: s.x + 10, y1: s.y + 10 });
      items.push({ s: s, text: agent.name + CanopyReplay.altitudeText(run, k, i), gap: 10, aboveFirst: false });
    });
    // People's symbols and names are placed whether shown or not, so that switching them off
    // does not move an agent's name.
    run.targets.forEach(function (target, t) {
      const q = run.target(k, t), s = view.toScreen(q.x, q.y);
      symbols.add({ x0: s.x - 6, y0: s.y - 6, x1: s.x + 6, y1: s.y + 6 });
      if (!crowd) items.unshift({ s: s, text: target.name, gap: 6, aboveFirst: true, shown: truth });
    });
    const line = 11;
    items.forEach(function (item) {
      const w = textWidth(ctx, item.text, font), g = item.gap;
      const aboveRight = [g, -g], belowRight = [g, g + line], aboveLeft = [-g - w, -g],
        belowLeft = [-g - w, g + line], farAbove = [-0.5 * w, -g - line], farBelow = [-0.5 * w, g + 2 * line];
      const places = item.aboveFirst ? [aboveRight, aboveLeft, belowRight, belowLeft, farAbove, farBelow]
        : [belowRight, belowLeft, aboveRight, aboveLeft, farBelow, farAbove];
      let chosen = null;
      for (let n = 0; n < places.length; n++) {
        const b = { x0: item.s.x + places[n][0], y0: item.s.y + places[n][1] - line,
          x1: item.s.x + places[n][0] + w, y1: item.s.y + places[n][1] + 2 };
        if (!symbols.hits(b) && !placed.hits(b)) {
          chosen = places[n];
          break;
        }
      }
      if (!chosen) return;  // no place fits: no name (a crowd at a far zoom)
      placed.add({ x0: item.s.x + chosen[0], y0: item.s.y + chosen[1] - line,
        x1: item.s.x + chosen[0] + w, y1: item.s.y + chosen[1] + 2 });
      if (item.shown !== false) CanopyReplay.label(ctx, item.s, item.text, chosen[0], chosen[1], view.ratio, font);
    });
  }
  CanopyReplay.Boxes = Boxes;
  CanopyReplay.textWidth = textWidth;
  CanopyReplay.drawNames = drawNames;
})();
