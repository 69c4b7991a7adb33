// The map's symbols: an agent's dart, a person's disc and a name on its halo, each drawn once into
// a small canvas (a sprite) and copied from there on every step; when the context draws vectors
// (an SVG export, svg_context.js) they are drawn as shapes and text instead.
/* global CanopyReplay */
(function () {
  "use strict";

  const C = CanopyReplay.COLOURS;
  const sprites = new Map();  // key → the sprite drawn once and copied: names, a person's disc

  // The sprite under `key`, drawn by draw(c) into a canvas of w × h CSS px at `ratio` device
  // pixels per px the first time it is asked for, and copied from the cache after. The canvas
  // is turned into an ImageBitmap in the background, which the browser copies faster; until it
  // is ready the canvas (the same pixels) is copied.
  function cachedSprite(key, w, h, ratio, draw) {
    const known = sprites.get(key);
    if (known) return known.bitmap || known.canvas;
    const canvas = document.createElement("canvas");
    canvas.width = Math.ceil(w * ratio);
    canvas.height = Math.ceil(h * ratio);
    const c = canvas.getContext("2d");
    c.setTransform(ratio, 0, 0, ratio, 0, 0);
    draw(c);
    const entry = { canvas: canvas, bitmap: null };
    sprites.set(key, entry);
    if (typeof createImageBitmap === "function") {
      createImageBitmap(canvas).then(function (bitmap) { entry.bitmap = bitmap; }, function () {});
    }
    return canvas;
  }

  function personDisc(c, x, y) {
    c.beginPath();
    c.arc(x, y, 5, 0, 2 * Math.PI);
    c.fillStyle = C.target;
    c.fill();
    c.strokeStyle = C.white;
    c.lineWidth = 1.5;
    c.stroke();
  }

  function drawTargets(ctx, view, run, k) {
    // A person's disc is drawn once into a small canvas and copied (stroking a few hundred
    // circles a step costs milliseconds).
    const ratio = view.ratio;
    if (ctx.vector) {
      for (let t = 0; t < run.targets.length; t++) {
        const q = run.target(k, t), s = view.toScreen(q.x, q.y);
        personDisc(ctx, s.x, s.y);
      }
      return;
    }
    const xs = [], ys = [];
    for (let t = 0; t < run.targets.length; t++) {
      const q = run.target(k, t), s = view.toScreen(q.x, q.y);
      if (!onMap(view, s, 7)) continue;
      // At whole device pixels: a copy that needs no resampling (half a pixel at most off).
      xs.push(Math.round(s.x * ratio) / ratio);
      ys.push(Math.round(s.y * ratio) / ratio);
    }
    if (xs.length > CanopyReplay.CROWD) {
      // A crowd (seen from far): each person an 8 px black square in a 1 px white rim, two fills
      // of one path each instead of a copy per person. As wide as the disc, it covers the
      // trails left out as under the disc (TRAIL_HIDDEN_PX and the line's half-width: 4.5 px).
      [[C.white, 5], [C.target, 4]].forEach(function (pass) {
        const h = pass[1];
        ctx.beginPath();
        for (let n = 0; n < xs.length; n++) ctx.rect(xs[n] - h, ys[n] - h, 2 * h, 2 * h);
        ctx.fillStyle = pass[0];
        ctx.fill();
      });
      return;
    }
    const sprite = cachedSprite("person " + ratio, 14, 14, ratio, function (c) { personDisc(c, 7, 7); });
    for (let n = 0; n < xs.length; n++) ctx.drawImage(sprite, xs[n] - 7, ys[n] - 7, sprite.width / ratio, sprite.height / ratio);
  }
  // More people than this on the map are a crowd: drawn as squares (drawTargets), without
  // their names (labels.js).
  CanopyReplay.CROWD = 64;

  // Whether screen point s lies on the map or within `margin` px of it.
  function onMap(view, s, margin) {
    return s.x >= -margin && s.y >= -margin && s.x <= view.width + margin && s.y <= view.height + margin;
  }

  // The number of people on the map (within 7 px of it) at step k.
  CanopyReplay.peopleOnMap = function (view, run, k) {
    let n = 0;
    for (let t = 0; t < run.targets.length; t++) {
      const q = run.target(k, t);
      if (onMap(view, view.toScreen(q.x, q.y), 7)) n++;
    }
    return n;
  };

  // The frames' dart (render/internal/tessellate.cpp): tip ahead, two back corners, a notch.
  function dart(ctx, s, yaw, size, fill) {
    const h = 0.5 * size, fx = Math.cos(yaw), fy = -Math.sin(yaw), sx = -fy, sy = fx;
    ctx.beginPath();
    ctx.moveTo(s.x + h * fx, s.y + h * fy);
    ctx.lineTo(s.x - h * fx + 0.8 * h * sx, s.y - h * fy + 0.8 * h * sy);
    ctx.lineTo(s.x - 0.45 * h * fx, s.y - 0.45 * h * fy);
    ctx.lineTo(s.x - h * fx - 0.8 * h * sx, s.y - h * fy - 0.8 * h * sy);
    ctx.closePath();
    ctx.fillStyle = fill;
    ctx.fill();
    ctx.strokeStyle = C.target;
    ctx.lineWidth = 1.2;
    ctx.stroke();
  }
  CanopyReplay.dart = dart;

  // An agent's dart (18 px, heading along +x) drawn once per colour into a small canvas and
  // copied turned to its heading: stroking 64 outlines a step costs more than 64 copies.
  function dartSprite(ctx, s, yaw, colour, ratio) {
    if (ctx.vector) {
      ctx.lineJoin = "round";
      dart(ctx, s, yaw, 18, colour);
      return;
    }
    const sprite = cachedSprite("dart " + ratio + " " + colour, 24, 24, ratio, function (c) {
      c.lineJoin = "round";
      dart(c, { x: 12, y: 12 }, 0, 18, colour);
    });
    const cos = Math.cos(yaw), sin = Math.sin(yaw);
    // Screen y points down: a heading yaw turns the sprite by -yaw on the screen.
    ctx.setTransform(ratio * cos, -ratio * sin, ratio * sin, ratio * cos, ratio * s.x, ratio * s.y);
    ctx.drawImage(sprite, -12, -12, 24, 24);
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  }

  function drawAgents(ctx, view, run, k) {
    run.agents.forEach(function (agent, i) {
      const p = run.uav(k, i);
      const s = view.toScreen(p.x, p.y);
      dartSprite(ctx, s, p.yaw, agent.colour, view.ratio);
      if (run.contactsAt(k, i)) {  // touching a trunk, wall or agent: a red ring, as the frames
        ctx.beginPath();
        ctx.arc(s.x, s.y, 13, 0, 2 * Math.PI);
        ctx.strokeStyle = C.contact;
        ctx.lineWidth = 2.5;
        ctx.stroke();
      }
    });
  }
  function haloText(c, text, x, y) {
    c.lineJoin = "round";
    c.lineWidth = 3;
    c.strokeStyle = "rgba(255,255,255,0.8)";
    c.strokeText(text, x, y);
    c.fillStyle = C.text;
    c.fillText(text, x, y);
  }

  // The sprite of a name in bold on a white halo (baseline at 15 px, left end at 3 px).
  function nameSprite(ctx, text, ratio, font) {
    return cachedSprite(ratio + "\n" + font + "\n" + text, CanopyReplay.textWidth(ctx, text, font) + 6, 20, ratio,
      function (c) {
        c.font = font;
        haloText(c, text, 3, 15);
      });
  }

  // Draws the sprites of the run's names (agents and people, at most MAX_WARM) at the page's start,
  // so that stepping through the run never stops to draw one.
  const MAX_WARM = 4096;
  CanopyReplay.warmNames = function (ctx, run, ratio) {
    const font = "bold " + CanopyReplay.FONT;
    run.agents.concat(run.targets).slice(0, MAX_WARM).forEach(function (x) { nameSprite(ctx, x.name, ratio, font); });
  };

  // A name in bold on a white halo, its baseline's left end at (s.x + dx, s.y + dy). Drawn once
  // into a small canvas of its own and copied from there: a few hundred names a step cost
  // copies, not text layout.
  function label(ctx, s, text, dx, dy, ratio, font) {
    if (ctx.vector) {
      haloText(ctx, text, s.x + dx, s.y + dy);
      return;
    }
    const sprite = nameSprite(ctx, text, ratio, font);
    ctx.drawImage(sprite, Math.round((s.x + dx - 3) * ratio) / ratio, Math.round((s.y + dy - 15) * ratio) / ratio,
      sprite.width / ratio, sprite.height / ratio);
  }
  CanopyReplay.drawTargets = drawTargets;
  CanopyReplay.drawAgents = drawAgents;
  CanopyReplay.label = label;
})();
