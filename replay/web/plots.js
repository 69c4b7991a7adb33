// The recorded fields the timeline can plot over the run for the selection: per field an id, a
// label and its value at every step (NaN where it has none). An agent: Σ tr P of its tracks, how
// many tracks it holds, its plan's cost (the plan of the epoch in force), the messages it sent at
// that epoch, the teammates' plans it received (held as planned against) and those it did not,
// its OSPA. A person: tr P of the shown agent's track of it, that track's error, how many agents
// see it, the agent's OSPA.
/* global CanopyReplay */
(function () {
  "use strict";

  function series(run, value) {
    const out = new Float64Array(run.steps);
    for (let k = 0; k < run.steps; k++) out[k] = value(k);
    return out;
  }

  // The plan of agent i in force at step k (the last epoch at or before k), or null.
  function planAt(run, k, i) {
    const e = run.epochAt[k];
    if (e < 0) return null;
    return run.epochs[e].plans.filter(function (p) { return p.agent === i; })[0] || null;
  }

  function agentFields(run, i) {
    return [
      { id: "trace", label: "\u03a3 tr P of its tracks (m\u00b2)", values: function () {
        return series(run, function (k) {
          return run.tracksAt(k, i).reduce(function (s, t) { return s + t.pxx + t.pyy; }, 0);
        });
      } },
      { id: "tracks", label: "tracks held", values: function () {
        return series(run, function (k) { return run.tracksAt(k, i).length; });
      } },
      { id: "cost", label: "plan cost", values: function () {
        return series(run, function (k) { const p = planAt(run, k, i); return p ? p.cost : NaN; });
      } },
      { id: "sent", label: "messages sent at the epoch", values: function () {
        return series(run, function (k) {
          const e = run.epochAt[k];
          return e < 0 ? NaN : run.epochs[e].sent.filter(function (m) { return m.from === i; }).length;
        });
      } },
      { id: "received", label: "teammates' plans received (held as planned against)", values: function () {
        return series(run, function (k) {
          return CanopyReplay.intentions(run, k, i).filter(function (x) { return x.status === "ok"; }).length;
        });
      } },
      { id: "missed", label: "teammates' plans not held", values: function () {
        return series(run, function (k) {
          return CanopyReplay.intentions(run, k, i).filter(function (x) { return x.status !== "ok"; }).length;
        });
      } },
      { id: "ospa", label: "OSPA (m)", values: function () { return Float64Array.from(run.ospa[i]); } }
    ].concat(CanopyReplay.altitudeFields(run, i));
  }

  function personFields(run, t, a) {
    const trackOf = function (k) {
      const j = run.trackOfTargetAt(k, a)[t];
      return j >= 0 ? run.tracksAt(k, a)[j] : null;
    };
    return [
      { id: "trace", label: "tr P of " + run.agents[a].name + "'s track (m\u00b2)", values: function () {
        return series(run, function (k) { const tr = trackOf(k); return tr ? tr.pxx + tr.pyy : NaN; });
      } },
      { id: "error", label: "error of " + run.agents[a].name + "'s track (m)", values: function () {
        return series(run, function (k) {
          const tr = trackOf(k), q = run.target(k, t);
          return tr ? Math.hypot(tr.x - q.x, tr.y - q.y) : NaN;
        });
      } },
      { id: "seen", label: "agents that see it", values: function () {
        return series(run, function (k) {
          let n = 0;
          for (let i = 0; i < run.agents.length; i++) if (run.visible[k][i].indexOf(t) >= 0) n++;
          return n;
        });
      } },
      { id: "ospa", label: "OSPA of " + run.agents[a].name + " (m)", values: function () { return Float64Array.from(run.ospa[a]); } }
    ];
  }

  // The fields of a selection ({kind, index}) seen through agent a.
  CanopyReplay.plotFields = function (run, selection, a) {
    return selection.kind === "agent" ? agentFields(run, selection.index) : personFields(run, selection.index, a);
  };
})();
