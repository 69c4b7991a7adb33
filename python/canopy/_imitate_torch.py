"""The PyTorch half of canopy.imitate: the Deep Sets policy (the same network as
agents/planning/policy_network.h), its policy-file export, and training by behaviour cloning then
DAgger. Imported only by ``train`` and the tests, so that the rest of canopy never needs torch."""
import json
import math
import os
import sys
import time

import torch
from torch import nn

from . import imitate

SELF, TRACK, MATE = imitate.FEATURES["self"], imitate.FEATURES["track"], imitate.FEATURES["mate"]


def _mlp(sizes, last_relu):
    layers = []
    for k in range(len(sizes) - 1):
        layers.append(nn.Linear(sizes[k], sizes[k + 1]))
        if last_relu or k + 2 < len(sizes):
            layers.append(nn.ReLU())
    return nn.Sequential(*layers)


class DeepSetsPolicy(nn.Module):
    """φ_T and φ_M: two dense layers each, ReLU after both; ρ: three dense layers, ReLU between;
    u = tanh(ρ([self, mean φ_T, max φ_T, mean φ_M, max φ_M])), an empty set pooling to zeros."""

    def __init__(self, hidden=32):
        super().__init__()
        self.track = _mlp([TRACK, hidden, hidden], True)
        self.mate = _mlp([MATE, hidden, hidden], True)
        self.head = _mlp([SELF + 4 * hidden, hidden, hidden, 2], False)

    @staticmethod
    def _pool(encoder, rows, mask):
        # rows (B, K, F), mask (B, K) 1 where a row is real.
        h = encoder(rows)
        m = mask.unsqueeze(-1)
        count = mask.sum(dim=1, keepdim=True)
        mean = (h * m).sum(dim=1) / count.clamp(min=1)
        neg = torch.full_like(h, -math.inf)
        mx = torch.where(m > 0, h, neg).max(dim=1).values
        mx = torch.where(count > 0, mx, torch.zeros_like(mx))
        return torch.cat([mean, mx], dim=1)

    def forward(self, own, tracks, track_mask, mates, mate_mask):
        z = torch.cat([own, self._pool(self.track, tracks, track_mask),
                       self._pool(self.mate, mates, mate_mask)], dim=1)
        return torch.tanh(self.head(z))


def batch(decisions, dtype=torch.float32):
    """Padded tensors (self, tracks, track mask, mates, mate mask) of observation dicts."""
    n = len(decisions)
    kt = max([len(d["tracks"]) for d in decisions] + [1])
    km = max([len(d["mates"]) for d in decisions] + [1])
    own = torch.tensor([d["self"] for d in decisions], dtype=dtype).reshape(n, SELF)
    tracks = torch.zeros(n, kt, TRACK, dtype=dtype)
    tmask = torch.zeros(n, kt, dtype=dtype)
    mates = torch.zeros(n, km, MATE, dtype=dtype)
    mmask = torch.zeros(n, km, dtype=dtype)
    for i, d in enumerate(decisions):
        if d["tracks"]:
            tracks[i, :len(d["tracks"])] = torch.tensor(d["tracks"], dtype=dtype)
            tmask[i, :len(d["tracks"])] = 1
        if d["mates"]:
            mates[i, :len(d["mates"])] = torch.tensor(d["mates"], dtype=dtype)
            mmask[i, :len(d["mates"])] = 1
    return own, tracks, tmask, mates, mmask


def targets(decisions, dtype=torch.float32):
    """The expert's action as a fraction of v_max per axis, inside (−1, 1) (tanh's range)."""
    u = [[a / d["v_max"] for a in d["expert"]] for d in decisions]
    return torch.tensor(u, dtype=dtype).clamp(-0.995, 0.995)


def policy_json(model, training=None):
    """The policy file (docs/imitation.md) of a model: every weight as a double."""
    def layers(seq):
        return [{"weight": m.weight.detach().double().tolist(), "bias": m.bias.detach().double().tolist()}
                for m in seq if isinstance(m, nn.Linear)]
    doc = {"format": "canopy-policy", "version": 1, "features": dict(imitate.FEATURES),
           "layers": {"track": layers(model.track), "mate": layers(model.mate),
                      "head": layers(model.head)}}
    if training is not None:
        doc["training"] = training
    return doc


def write_policy(model, path, training=None):
    tmp = f"{path}.tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        json.dump(policy_json(model, training), f)
    os.replace(tmp, path)


def fit(model, decisions, epochs, seed, lr=3e-3, batch_size=64, log=None):
    """Minimises the mean squared error between u and the expert's u over `decisions` (Adam,
    shuffled mini-batches from a generator seeded with `seed`). Returns the per-epoch losses."""
    data = batch(decisions)
    y = targets(decisions)
    n = y.shape[0]
    generator = torch.Generator().manual_seed(seed)
    opt = torch.optim.Adam(model.parameters(), lr=lr)
    losses = []
    for epoch in range(epochs):
        order = torch.randperm(n, generator=generator)
        total = 0.0
        for start in range(0, n, batch_size):
            idx = order[start:start + batch_size]
            pred = model(*(t[idx] for t in data))
            loss = ((pred - y[idx]) ** 2).mean()
            opt.zero_grad()
            loss.backward()
            opt.step()
            total += loss.item() * len(idx)
        losses.append(total / n)
        if log:
            log(epoch, losses[-1])
    return losses


def disagreement(decisions):
    """Mean squared difference between flown and expert u: how far the flying policy is from the
    expert on the states it visits (DAgger's measure)."""
    total = 0.0
    for d in decisions:
        total += sum((f / d["v_max"] - e / d["v_max"]) ** 2 for f, e in zip(d["flown"], d["expert"])) / 2
    return total / max(1, len(decisions))


def _bar(done, total, text, width=30):
    filled = int(width * done / max(1, total))
    sys.stderr.write(f"\r[{'#' * filled}{'.' * (width - filled)}] {text}")
    sys.stderr.flush()


def plot(curve, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(range(1, len(curve["loss"]) + 1), curve["loss"], label="training loss (MSE of u)")
    for r in curve["rounds"]:
        ax.axvline(r["first_epoch"] + 0.5, color="0.8", lw=0.8)
    xs = [r["first_epoch"] + 1 for r in curve["rounds"] if r["on_policy"] is not None]
    ys = [r["on_policy"] for r in curve["rounds"] if r["on_policy"] is not None]
    if xs:
        ax.plot(xs, ys, "o-", label="on-policy disagreement with SMA-NBO (DAgger rounds)")
    ax.set_yscale("log")
    ax.set_xlabel("epoch (grey lines: a new round's data)")
    ax.set_ylabel("mean squared error of u = a / v_max")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def train_command(args):
    torch.manual_seed(args.seed)
    torch.set_num_threads(1)
    torch.use_deterministic_algorithms(True)
    os.makedirs(args.out, exist_ok=True)
    start = time.monotonic()
    model = DeepSetsPolicy(args.hidden)
    policy = os.path.join(args.out, "policy.json")
    data, curve = [], {"loss": [], "rounds": []}
    log_path = os.path.join(args.out, "training.jsonl")
    log = open(log_path, "w", encoding="utf-8")
    total_rounds = args.dagger + 1
    for r in range(total_rounds):
        demos = os.path.join(args.out, f"demonstrations_{r}.jsonl")
        overrides = list(args.set)
        if r > 0:
            overrides += ["planner.algorithm=learned", f"planner.policy={os.path.abspath(policy)}"]
        _bar(r, total_rounds, f"round {r}/{args.dagger}: collecting {args.trials} trials "
                              f"({'SMA-NBO flies' if r == 0 else 'the policy flies, SMA-NBO labels'})")
        imitate.collect(args.scenario, demos, args.trials, args.seed, overrides, args.jobs,
                        allow=[os.path.abspath(args.out)])
        new = imitate.read_demonstrations(demos)[1]
        on_policy = disagreement(new) if r > 0 else None
        data += new
        first = len(curve["loss"])

        def progress(epoch, loss, r=r):
            _bar(r + (epoch + 1) / args.epochs, total_rounds,
                 f"round {r}/{args.dagger}: epoch {epoch + 1}/{args.epochs} loss {loss:.4g} "
                 f"({len(data)} decisions)   ")
        losses = fit(model, data, args.epochs, args.seed + r, log=progress)
        curve["loss"] += losses
        entry = {"round": r, "decisions": len(data), "new": len(new), "first_epoch": first,
                 "loss": losses[-1], "on_policy": on_policy,
                 "seconds": round(time.monotonic() - start, 1)}
        curve["rounds"].append(entry)
        log.write(json.dumps(entry) + "\n")
        log.flush()
        training = {"scenario": args.scenario, "trials": args.trials, "seed": args.seed,
                    "rounds": r + 1, "epochs": args.epochs, "hidden": args.hidden,
                    "decisions": len(data), "overrides": list(args.set),
                    "command": "python3 -m canopy.imitate " + " ".join(sys.argv[1:])}
        write_policy(model, policy, training)
    log.close()
    torch.save({"model": model.state_dict(), "hidden": args.hidden, "curve": curve},
               os.path.join(args.out, "checkpoint.pt"))
    plot(curve, os.path.join(args.out, "learning_curve.png"))
    sys.stderr.write("\n")
    print(f"{policy}: trained in {time.monotonic() - start:.0f} s on {len(data)} decisions; "
          f"final loss {curve['loss'][-1]:.4g}")
    return 0
