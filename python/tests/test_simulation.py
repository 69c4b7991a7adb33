"""Stepping from Python: commands (zero keeps still, clamped to v_max, bad input raises), the
clock, zero-copy truth views, copies of beliefs, and rendering through the CLI's renderer."""
import gc

import numpy as np
import pytest

import canopy
from png_reader import read_png


@pytest.fixture
def demo():
    return canopy.Simulation(canopy.load("demo"), seed=5)


def test_construction_runs_step_zero(demo):
    assert demo.step_index == 0 and demo.time == 0.0 and not demo.done
    # demo.json: clock.dt = 0.2, duration = 30 → K = 150, and 151 steps k = 0..150 recorded: the
    # number `canopy validate demo` prints (issue 51: Python said 150 where the CLI said 151).
    assert demo.dt == 0.2 and demo.last_step == 150 and demo.steps == 151
    demo.step()
    demo.step()
    assert demo.step_index == 2 and demo.time == pytest.approx(0.4)


def test_runs_to_k_then_refuses(demo):
    while not demo.done:
        demo.step()
    assert demo.step_index == 150
    with pytest.raises(RuntimeError, match="done"):
        demo.step()


def test_zero_commands_keep_uavs_still(demo):
    demo.step()
    start = demo.uav_states.copy()
    for _ in range(10):
        demo.step(np.zeros((2, 2)))
        np.testing.assert_array_equal(demo.uav_states, start)
        np.testing.assert_array_equal(demo.uav_velocities, 0.0)


def test_commands_above_v_max_are_clamped(demo):
    v_max = demo.v_max
    assert list(v_max) == [5.0, 5.0]  # demo.json gives both UAVs v_max 5 m/s
    before = demo.uav_states[:, :2].copy()
    # (30, 40) is 50 m/s along (0.6, 0.8): clamped to 5 m/s → (3, 4). (1, -2) is below 5.
    demo.step(np.array([[30.0, 40.0], [1.0, -2.0]]))
    np.testing.assert_allclose(demo.uav_velocities, [[3.0, 4.0], [1.0, -2.0]], atol=1e-5)
    # Box2D holds positions in single precision: a 0.2 s step moves (0.6, 0.8) and (0.2, −0.4).
    np.testing.assert_allclose(demo.uav_states[:, :2] - before, [[0.6, 0.8], [0.2, -0.4]],
                               atol=1e-4)


def test_a_command_lasts_one_step(demo):
    demo.step()
    planned = demo.uav_commands.copy()  # the script's command for the next step
    demo.step(np.zeros((2, 2)))
    np.testing.assert_array_equal(demo.uav_velocities, 0.0)
    planned = demo.uav_commands.copy()
    demo.step()  # no command: the script flies again
    np.testing.assert_allclose(demo.uav_velocities, planned, atol=1e-5)


def test_lists_are_accepted_as_commands(demo):
    demo.step([[1, 0], [0, 1]])
    np.testing.assert_allclose(demo.uav_velocities, [[1, 0], [0, 1]], atol=1e-6)


@pytest.mark.parametrize("commands, error, text", [
    (np.zeros((3, 2)), ValueError, r"expected shape \(2, 2\).*got \(3, 2\)"),
    (np.zeros(4), ValueError, r"got \(4,\)"),
    (np.zeros((2, 2, 1)), ValueError, r"got \(2, 2, 1\)"),
    ([[np.nan, 0], [0, 0]], ValueError, r"commands\[0\]: expected a finite velocity"),
    ([[0, 0], [0, np.inf]], ValueError, r"commands\[1\]"),
    # Wrong types are canopy.ScenarioError (a ValueError) naming the argument, as every other
    # refusal of a public entry point.
    ("fast", ValueError, "commands: expected an array of numbers"),
    ([[0, "a"], [0, 0]], ValueError, "commands: expected an array of numbers"),
])
def test_bad_commands_raise_and_change_nothing(demo, commands, error, text):
    before = demo.uav_states.copy()
    with pytest.raises(error, match=text):
        demo.step(commands)
    assert demo.step_index == 0
    np.testing.assert_array_equal(demo.uav_states, before)
    demo.step(np.zeros((2, 2)))  # still usable
    assert demo.step_index == 1


def test_truth_views_are_live_read_only_and_keep_the_simulation(demo):
    uavs, targets = demo.uav_states, demo.target_states
    assert uavs.shape == (2, 3) and targets.shape == (3, 4)
    assert not uavs.flags.writeable and not uavs.flags.owndata
    assert demo.uav_states is uavs  # one view, handed out at every step: no allocation
    with pytest.raises(ValueError):
        uavs[0, 0] = 1.0
    demo.step([[1, 0], [1, 0]])
    np.testing.assert_array_equal(uavs, demo.uav_states)  # the same memory, now step 1
    del demo
    gc.collect()
    assert np.isfinite(uavs).all()  # the view keeps the simulation alive


def test_truth_matches_the_scenario_start():
    s = canopy.load("trajectory_handover")
    sim = canopy.Simulation(s)
    np.testing.assert_array_equal(sim.uav_states, [[-9, 0, 0], [9, 0, 0]])
    # Target I walks from (−9, 3) to (−3, 27) in 12 s; at k = 0 its record has v = 0 (no step yet).
    np.testing.assert_array_equal(sim.target_states[0], [-9, 3, 0, 0])
    sim.step()
    np.testing.assert_allclose(sim.target_states[0], [-9 + 0.1, 3 + 0.4, 0.5, 2.0], atol=1e-5)


def test_beliefs_are_arrays_of_the_documented_shapes():
    sim = canopy.Simulation(canopy.load("trajectory_handover"), seed=3)
    sim.step()
    tracks = sim.tracks(1)
    m = len(tracks["keys"])
    assert m == 4  # pre-seeded: one track per target
    assert tracks["means"].shape == (m, 4) and tracks["covariances"].shape == (m, 4, 4)
    P = tracks["covariances"]
    np.testing.assert_allclose(P, P.transpose(0, 2, 1), rtol=0, atol=1e-12)
    assert (np.linalg.eigvalsh(P) > 0).all()
    truth = sim.target_states
    assert np.abs(tracks["means"][:, :2] - truth[:, :2]).max() < 3.0
    scan = sim.scan(0)
    assert scan["z"].shape[1:] == (2,) and scan["R"].shape[1:] == (2, 2)
    assert set(scan["visible"]) <= set(scan["in_footprint"])
    assert sim.plan is not None and sim.plan["commands"].shape == (2, 2)
    assert sim.planned_path(0).shape == (5, 2)  # planner.horizon = 5
    with pytest.raises(IndexError):
        sim.tracks(2)


def test_occlusion_map_holds_seen_trees():
    s = canopy.load("occlusion_sharing")
    # One crown of radius 2 m, 3 m from UAV1's start (−9.6, 1.6): inside its 12 × 12 m footprint.
    s.config["occluders"] = [canopy.forest.disc((-6.6, 1.6), 2.0)]
    sim = canopy.Simulation(s, seed=1)
    for _ in range(5):
        sim.step(np.zeros((2, 2)))
    tree = sim.occlusion_map(0)
    assert tree["means"].shape == (1, 3) and tree["covariances"].shape == (1, 3, 3)
    np.testing.assert_allclose(tree["means"][0], [-6.6, 1.6, 2.0], atol=0.5)
    assert len(tree["outlines"]) == 1 and tree["outlines"][0].shape == (0, 2)  # a disc


def test_occlusion_map_holds_a_walls_outline():
    s = canopy.load("occlusion_sharing")
    # A 6 × 1 m wall inside UAV1's footprint: mapped as its four corners, in the file's order.
    corners = [[-12, 0], [-6, 0], [-6, 1], [-12, 1]]
    s.config["occluders"] = [{"type": "polygon", "vertices": corners}]
    sim = canopy.Simulation(s, seed=1)
    for _ in range(10):
        sim.step(np.zeros((2, 2)))
    outlines = sim.occlusion_map(0)["outlines"]
    assert len(outlines) == 1 and outlines[0].shape == (4, 2)
    np.testing.assert_allclose(outlines[0], corners, atol=0.5)


def test_render_equals_the_clis_first_frame(tmp_path, cli):
    cli("run", "demo", "--seed", "5", "--frames", "--size", "320x240", "--out", tmp_path)
    sim = canopy.Simulation(canopy.load("demo"), seed=5)
    image = sim.render(320, 240)
    assert image.shape == (240, 320, 3) and image.dtype == np.uint8
    np.testing.assert_array_equal(image, read_png(tmp_path / "frames" / "frame_000000.png"))


def test_render_rejects_bad_sizes(demo):
    with pytest.raises(ValueError, match="width and height"):
        demo.render(0, 100)


def test_step_takes_none_or_one_argument(demo):
    demo.step(None)
    demo.step()
    assert demo.step_index == 2
    with pytest.raises(TypeError, match="at most one argument"):
        demo.step(np.zeros((2, 2)), np.zeros((2, 2)))


def test_a_simulation_per_episode_reuses_the_loaded_scenario():
    s = canopy.load("demo")
    first = s._spec()
    canopy.Simulation(s)
    assert s._spec() is first  # unchanged configuration: not loaded again
    s["uavs.0.v_max"] = 2.0
    sim = canopy.Simulation(s)
    assert s._spec() is not first and list(sim.v_max) == [2.0, 5.0]


@pytest.mark.parametrize("use", [
    lambda s: s.step(), lambda s: s.step([[0, 0], [0, 0]]), lambda s: s.done, lambda s: s.uav_states,
    lambda s: s.target_states, lambda s: s.uav_velocities, lambda s: s.tracks(0), lambda s: s.scan(0),
    lambda s: s.occlusion_map(0), lambda s: s.plan, lambda s: s.v_max, lambda s: s.render(64, 64),
    lambda s: s.record_line(), lambda s: s.time,
])
def test_a_simulation_without_init_raises_instead_of_crashing(use):
    s = canopy.Simulation.__new__(canopy.Simulation)
    with pytest.raises(RuntimeError, match="not initialised"):
        use(s)


def test_methods_refuse_other_objects_as_self():
    with pytest.raises(TypeError, match="expected a canopy.Simulation"):
        canopy.Simulation.tracks(42, 0)


def test_climb_commands_move_a_uav_with_altitude_limits():
    # Issue 53: altitude_tradeoff's UAVs fly between 10 and 60 m at up to 2 m/s. A third column
    # of 2 m/s for 5 steps of 0.2 s climbs 2 m; −10 m/s is clamped to −2 m/s.
    sim = canopy.Simulation(canopy.load("altitude_tradeoff"), seed=1)
    assert list(sim.uav_altitudes) == [20.0, 20.0]
    up = np.zeros((2, 3))
    up[0, 2] = 2.0
    for _ in range(5):
        sim.step(up)
    assert sim.uav_altitudes[0] == pytest.approx(22.0)
    down = np.zeros((2, 3))
    down[1, 2] = -10.0
    sim.step(down)
    assert sim.uav_altitudes[1] == pytest.approx(20.0 - 0.4)
    with pytest.raises(canopy.ScenarioError, match=r"\(2, 3\)"):
        sim.step(np.zeros((2, 4)))
