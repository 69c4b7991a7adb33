"""Scenarios as objects: load with overrides, edit, validate with the CLI's messages, save."""
import json
import math

import numpy as np
import pytest

import canopy


def test_load_applies_overrides_and_fills_defaults():
    s = canopy.load("demo", overrides={"planner.horizon": 1, "uavs.1.v_max": 2.5})
    assert s["planner.horizon"] == 1
    assert s.uavs[1]["v_max"] == 2.5
    # demo.json says nothing of fusion.rounds; the loader's default (5) is filled in.
    assert s["fusion.rounds"] == 5
    assert s.name == "demo" and s.file.endswith("scenarios/library/demo.json")


def test_unknown_override_raises_naming_the_field():
    with pytest.raises(canopy.ScenarioError) as e:
        canopy.load("demo", overrides={"planner.horizonn": 1})
    assert "planner.horizonn" in str(e.value)


def test_validate_error_is_the_clis(tmp_path, cli):
    s = canopy.load("demo")
    s.config["uavs"][0]["v_max"] = -1.0  # by hand: an edit through [] is refused at once
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(s.config))
    bad = canopy.Scenario(json.loads(path.read_text()), file=path)
    with pytest.raises(canopy.ScenarioError) as e:
        bad.validate()
    assert e.value.file == str(path)
    assert e.value.field == "uavs[0].v_max"
    done = cli("validate", path, check=False)
    assert done.returncode == 2
    # The CLI reads the file itself and names the line (json.dumps wrote one); Python checked a
    # configuration, not the file's text, so it names none.
    assert done.stderr.strip() == f"canopy: {e.value} (line 1)"


def test_wrong_type_names_the_field():
    s = canopy.load("demo")
    s.config["clock"]["dt"] = "fast"
    with pytest.raises(canopy.ScenarioError) as e:
        s.validate()
    assert e.value.field == "clock.dt"


@pytest.mark.parametrize("path, value, field, reason", [
    ("uavs.0.vmax", 3.0, "uavs[0].vmax", "unknown field"),
    ("uavs.0.v_max", float("nan"), "uavs[0].v_max", "expected a finite number"),
    ("uavs.0.v_max", float("inf"), "uavs[0].v_max", "expected a finite number"),
    ("uavs.0.v_max", -3.0, "uavs[0].v_max", "expected a positive number"),
    ("clock.dt", "fast", "clock.dt", "expected a positive number"),
    ("uavs.1.fov", {"radius": 5, "size": [1, 1]}, "uavs[1].fov", "give only one of"),
])
def test_an_edit_is_checked_as_it_is_made_and_undone_when_refused(path, value, field, reason):
    s = canopy.load("demo")
    before = json.dumps(s.config, sort_keys=True)
    with pytest.raises(canopy.ScenarioError) as e:
        s[path] = value
    assert isinstance(e.value, ValueError)
    assert e.value.field == field and reason in str(e.value), str(e.value)
    assert "line" not in str(e.value)  # the text checked is not the file's: no line to blame
    assert json.dumps(s.config, sort_keys=True) == before


def test_deleting_a_field_restores_its_default():
    s = canopy.load("demo")  # demo sets tracking.sigma_a to 1.0 and fusion.rounds to 5
    bare = canopy.Scenario({"aoi": [0, 0, 10, 10], "uavs": [{"start": [1, 1]}]}).filled()
    del s["tracking.sigma_a"]
    del s["fusion.rounds"]
    assert s["tracking.sigma_a"] == bare["tracking.sigma_a"]
    assert s["fusion.rounds"] == bare["fusion.rounds"]
    del s["targets.2"]  # a list element goes from its list
    assert [t["name"] for t in s.targets] == ["T1", "T2"]
    with pytest.raises(canopy.ScenarioError, match=r"uavs"):
        del s["uavs"]  # required: refused, and the UAVs stay
    assert len(s.uavs) == 2


def test_missing_path_is_a_key_error():
    s = canopy.load("demo")
    with pytest.raises(KeyError, match="no such field"):
        s["planner.pso.nothing.here"] = 1
    with pytest.raises(KeyError, match="no element 7"):
        s["uavs.7"] = {}


def test_saved_file_is_valid_for_the_cli_and_loads_back_equal(tmp_path, cli):
    s = canopy.load("demo")
    s.occluders.append(canopy.forest.disc((10, -10), 2.0))
    s["targets.0.name"] = "walker"
    path = s.save(tmp_path / "edited.json")
    cli("validate", path)
    again = canopy.load(path)
    assert again.config == s.filled().config
    assert again.occluders[-1] == {"type": "disc", "centre": [10.0, -10.0], "radius": 2.0}


def test_invalid_scenario_is_not_saved(tmp_path):
    s = canopy.load("demo")
    with pytest.raises(canopy.ScenarioError, match="aoi"):
        s["aoi"] = [0, 0, -1, 1]  # refused as it is made
    s.config["aoi"] = [0, 0, -1, 1]  # by hand, past the check
    with pytest.raises(canopy.ScenarioError, match="aoi"):
        s.save(tmp_path / "x.json")
    assert not list(tmp_path.iterdir())


def test_poisson_equals_the_cli_forest(cli):
    trees = canopy.forest.poisson((0, 0, 100, 100), 0.01, (1, 2.5), seed=3)
    printed = json.loads(cli("forest", "--aoi", "0,0,100,100", "--lambda", "0.01", "--radius",
                             "1,2.5", "--seed", "3").stdout)["occluders"]
    assert trees == printed


def test_poisson_statistics():
    # λ·A = 0.02 · 200 · 200 = 800 trees expected; a Poisson count has σ = √800 ≈ 28.
    trees = canopy.forest.poisson((0, 0, 200, 200), 0.02, (1.0, 2.0), seed=11)
    assert abs(len(trees) - 800) < 4 * math.sqrt(800)
    c = np.array([t["centre"] for t in trees])
    r = np.array([t["radius"] for t in trees])
    assert (c >= 0).all() and (c <= 200).all()
    assert r.min() >= 1.0 and r.max() <= 2.0


def test_poisson_min_gap_keeps_crowns_apart():
    trees = canopy.forest.poisson((0, 0, 100, 100), 0.02, 1.5, seed=4, min_gap=2.0)
    c = np.array([t["centre"] for t in trees])
    d = np.linalg.norm(c[:, None, :] - c[None, :, :], axis=2) + np.eye(len(c)) * 1e9
    assert d.min() >= 2 * 1.5 + 2.0 - 1e-9
    # Matérn II for equal radii: (1 − exp(−λπD²)) / (πD²) per m², D = 2r + gap = 5 m.
    expected = (1 - math.exp(-0.02 * math.pi * 25)) / (math.pi * 25) * 100 * 100
    assert abs(len(trees) - expected) < 4 * math.sqrt(expected)


def test_grid_positions_by_hand():
    trees = canopy.forest.grid(origin=(1, 2), spacing=(10, 5), rows=2, cols=3, radius=1.5)
    centres = [t["centre"] for t in trees]
    expected = [[1 + 10 * c, 2 + 5 * r] for r in range(2) for c in range(3)]
    assert sorted(centres) == sorted(expected)
    assert all(t["radius"] == 1.5 for t in trees)


def test_cluster_trees_stay_in_the_region():
    trees = canopy.forest.cluster((0, 0, 300, 300), 1e-4, 8, 5.0, 1.0, seed=2)
    c = np.array([t["centre"] for t in trees])
    assert len(trees) > 0 and (c >= 0).all() and (c <= 300).all()


def test_generator_errors_name_the_generator_and_field():
    with pytest.raises(canopy.ScenarioError) as e:
        canopy.forest.poisson((0, 0, 10, 10), -1, 1)
    assert e.value.file == "canopy.forest.poisson"
    assert "lambda" in e.value.field
    with pytest.raises(canopy.ScenarioError, match="radius"):
        canopy.forest.grid((0, 0), (1, 1), 2, 2, radius=(3, 1))
