// Two runs compared (`canopy view A B`, side by side or --overlay): which agent or person of one
// run stands for a given one of the other (the same name, else the same place in its list), and
// the legend's words saying which run is which. A page of one run has no letter and shows none.
/* global CanopyReplay */
(function () {
  "use strict";

  // The index in `to`'s list of the entity named as `from`'s entry i: the same name, else the
  // same index when `to` has one, else -1.
  function counterpartIndex(fromList, toList, i) {
    if (i < 0 || i >= fromList.length) return -1;
    const name = fromList[i].name;
    for (let n = 0; n < toList.length; n++) if (toList[n].name === name) return n;
    return i < toList.length ? i : -1;
  }

  CanopyReplay.counterpartAgent = function (from, to, i) {
    return counterpartIndex(from.agents, to.agents, i);
  };

  // A selection ({kind: "agent"|"target", index}) of run `from` in run `to`, or null.
  CanopyReplay.counterpart = function (from, to, selection) {
    if (!selection) return null;
    const agent = selection.kind === "agent";
    const n = counterpartIndex(agent ? from.agents : from.targets, agent ? to.agents : to.targets, selection.index);
    return n < 0 ? null : { kind: selection.kind, index: n };
  };

  // "run A (folder): scenario, seed S".
  CanopyReplay.runTitle = function (run) {
    return "run " + (run.letter || "") + (run.folder ? " (" + run.folder + ")" : "") + ": " + run.scenario +
      ", seed " + run.seed;
  };

  function legendRow(text, draw, id) {
    const legend = document.getElementById("legend"), row = document.createElement("div");
    const swatch = document.createElement("canvas");
    swatch.width = 26;
    swatch.height = 18;
    swatch.style.width = "26px";
    swatch.style.height = "18px";
    draw(swatch.getContext("2d"));
    const words = document.createElement("span");
    words.textContent = text;
    row.id = id;
    row.className = "run-entry";
    row.appendChild(swatch);
    row.appendChild(words);
    legend.insertBefore(row, legend.children[1] || null);  // under the legend's heading
    return row;
  }

  // The darts a run is drawn with: run A's filled, a second run's over it hollow.
  function solidDart(colour) {
    return function (ctx) { CanopyReplay.dart(ctx, { x: 13, y: 9 }, Math.PI / 2, 14, colour); };
  }
  function hollowDart(colour) {
    return function (ctx) {
      CanopyReplay.dart(ctx, { x: 13, y: 9 }, Math.PI / 2, 14, "rgba(255,255,255,0.6)");
      ctx.strokeStyle = colour;
      ctx.lineWidth = 2;
      ctx.stroke();
    };
  }

  // The legend's first entries name the runs of a comparison page: this page's run, and in an
  // overlay the second run and how it is drawn; side by side (`other`: the run beside this one),
  // that it is shown beside. Nothing on a page of one run.
  CanopyReplay.markRuns = function (app, other) {
    const run = app.run, second = app.state.second, colour = run.agents.length ? run.agents[0].colour : "#444";
    Array.from(document.querySelectorAll("#legend .run-entry")).forEach(function (row) { row.remove(); });
    if (second) {
      legendRow(CanopyReplay.runTitle(second.run) + ", drawn over run A: hollow darts, dashed footprints, " +
        "occlusion map and plans, tracks as + with dashed ellipses and labels \u201cB track\u201d, people as rings",
        hollowDart(colour), "run-b-entry");
    }
    if (!run.letter) return;
    legendRow(CanopyReplay.runTitle(run) + (second ? ": filled darts and footprints, solid lines, tracks as \u00d7"
      : other ? ", this page; " + CanopyReplay.runTitle(other) + " beside it" : ""), solidDart(colour), "run-a-entry");
    if (!second) document.getElementById("run-a-entry").id = "run-entry";
    document.getElementById("scenario").textContent = "run " + run.letter + ": " + run.scenario;
  };
})();
