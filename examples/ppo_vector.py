"""PPO in PyTorch on canopy.VectorEnv: one policy flies the whole team, trained on n episodes
stepped at once in C++, and its learning curve plotted (issue 51). No RL library is packaged in
Debian; PyTorch is (`apt-get install python3-torch`, about 1 GB with its dependencies: only this
example needs it).

    PYTHONPATH=build/release/python /usr/bin/python3 examples/ppo_vector.py [--out out/ppo]
        [--scenario trajectory_handover] [--envs 8] [--iterations 40] [--steps 32] [--seed 1]

Writes OUT/learning_curve.csv (iteration, env steps, mean return of the episodes that ended) and
OUT/learning_curve.{pdf,png} (matplotlib). The return is the team's: the sum over steps of the
sum over agents of −Σ tr(P) of each agent's fused tracks (README, "Python"), so it rises towards
0 as the team keeps its people better tracked. Gymnasium's RecordEpisodeStatistics would count
the same returns where Gymnasium is installed; here the loop counts them itself.
"""
import argparse
import csv
import os

import numpy as np
import torch
from torch import nn

import canopy


class Policy(nn.Module):
    """A Gaussian policy over the team's velocities and a value function, from the flattened
    observations of every agent."""

    def __init__(self, obs_size, act_size):
        super().__init__()
        self.body = nn.Sequential(nn.Linear(obs_size, 128), nn.Tanh(), nn.Linear(128, 128), nn.Tanh())
        self.mean = nn.Linear(128, act_size)
        self.value = nn.Linear(128, 1)
        self.log_std = nn.Parameter(torch.full((act_size,), -0.5))

    def forward(self, obs):
        h = self.body(obs)
        return torch.distributions.Normal(self.mean(h), self.log_std.exp()), self.value(h).squeeze(-1)


def train(args):
    torch.manual_seed(args.seed)
    scenario = canopy.load(args.scenario, overrides={"clock.duration": args.duration})
    envs = canopy.VectorEnv(args.envs, scenario, autoreset_mode="SameStep")
    n = envs.num_envs
    obs_shape, act_shape = envs.single_observation_space.shape, envs.single_action_space.shape
    v_max = torch.as_tensor(np.array(envs.single_action_space.high).reshape(-1))
    low, high = envs.single_observation_space.low, envs.single_observation_space.high
    scale = torch.as_tensor(np.maximum(np.abs(low), np.abs(high)).reshape(-1).clip(1e-3, 1e3))
    policy = Policy(int(np.prod(obs_shape)), int(np.prod(act_shape)))
    optimiser = torch.optim.Adam(policy.parameters(), lr=3e-4)

    def observe(o):
        return torch.as_tensor(o.reshape(n, -1), dtype=torch.float32) / scale

    obs, _ = envs.reset(seed=args.seed)
    obs = observe(obs)
    returns_now, curve, finished = np.zeros(n), [], []
    for iteration in range(args.iterations):
        batch = {k: [] for k in ("obs", "act", "logp", "rew", "done", "value")}
        for _ in range(args.steps):
            with torch.no_grad():
                dist, value = policy(obs)
                action = dist.sample()
            velocity = (torch.tanh(action) * v_max).numpy().reshape((n,) + act_shape)
            next_obs, reward, term, trunc, _ = envs.step(velocity)
            done = np.logical_or(term, trunc)
            returns_now += reward
            finished.extend(returns_now[done])
            returns_now[done] = 0.0
            for k, v in (("obs", obs), ("act", action), ("logp", dist.log_prob(action).sum(-1)),
                         ("rew", torch.as_tensor(reward * args.reward_scale, dtype=torch.float32)),
                         ("done", torch.as_tensor(done, dtype=torch.float32)), ("value", value)):
                batch[k].append(v)
            obs = observe(next_obs)
        with torch.no_grad():
            _, last_value = policy(obs)
        b = {k: torch.stack(v) for k, v in batch.items()}
        advantages, gae = torch.zeros_like(b["rew"]), torch.zeros(n)
        for t in reversed(range(args.steps)):  # generalised advantage estimation
            following = last_value if t == args.steps - 1 else b["value"][t + 1]
            delta = b["rew"][t] + args.gamma * following * (1 - b["done"][t]) - b["value"][t]
            gae = delta + args.gamma * args.lam * (1 - b["done"][t]) * gae
            advantages[t] = gae
        targets = (advantages + b["value"]).reshape(-1)
        flat = {k: v.reshape((-1,) + v.shape[2:]) for k, v in b.items()}
        adv = advantages.reshape(-1)
        adv = (adv - adv.mean()) / (adv.std() + 1e-8)
        for _ in range(args.epochs):
            for idx in torch.randperm(len(adv)).split(args.minibatch):
                dist, value = policy(flat["obs"][idx])
                ratio = (dist.log_prob(flat["act"][idx]).sum(-1) - flat["logp"][idx]).exp()
                clipped = torch.clamp(ratio, 1 - args.clip, 1 + args.clip)
                loss = (-torch.min(ratio * adv[idx], clipped * adv[idx]).mean()
                        + 0.5 * ((value - targets[idx]) ** 2).mean() - 0.001 * dist.entropy().sum(-1).mean())
                optimiser.zero_grad()
                loss.backward()
                nn.utils.clip_grad_norm_(policy.parameters(), 0.5)
                optimiser.step()
        mean_return = float(np.mean(finished)) if finished else float("nan")
        curve.append((iteration + 1, (iteration + 1) * args.steps * n, mean_return, len(finished)))
        print(f"iteration {iteration + 1:3d}: {len(finished):3d} episodes, mean return {mean_return:10.1f}",
              flush=True)
        finished = []
    envs.close()
    return curve


def plot(curve, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    steps = [c[1] for c in curve]
    returns = [c[2] for c in curve]
    figure, axes = plt.subplots(figsize=(6, 3.5))
    axes.plot(steps, returns, marker="o", markersize=3)
    axes.set_xlabel("environment steps")
    axes.set_ylabel("mean team return per episode")
    axes.set_title("PPO on canopy.VectorEnv")
    axes.grid(alpha=0.3)
    figure.tight_layout()
    for extension in ("pdf", "png"):
        figure.savefig(os.path.join(out, f"learning_curve.{extension}"))
    plt.close(figure)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default="out/ppo")
    parser.add_argument("--scenario", default="trajectory_handover")
    parser.add_argument("--duration", type=float, default=6.0, help="s of each episode")
    parser.add_argument("--envs", type=int, default=8)
    parser.add_argument("--iterations", type=int, default=40)
    parser.add_argument("--steps", type=int, default=32, help="steps of every env per iteration")
    parser.add_argument("--epochs", type=int, default=4)
    parser.add_argument("--minibatch", type=int, default=64)
    parser.add_argument("--gamma", type=float, default=0.99)
    parser.add_argument("--lam", type=float, default=0.95)
    parser.add_argument("--clip", type=float, default=0.2)
    parser.add_argument("--reward-scale", type=float, default=0.01)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    curve = train(args)
    with open(os.path.join(args.out, "learning_curve.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["iteration", "env_steps", "mean_return", "episodes"])
        writer.writerows(curve)
    plot(curve, args.out)
    print(f"learning curve: {args.out}/learning_curve.csv, .pdf, .png")


if __name__ == "__main__":
    main()
