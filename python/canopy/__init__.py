"""canopy from Python: scenarios as objects, layout generators, stepping with your own commands,
multi-agent environments (PettingZoo ParallelEnv, many at once on threads).

    import canopy
    scenario = canopy.load("demo", overrides={"planner.horizon": 1})
    scenario.validate()            # raises canopy.ScenarioError naming the file and the field
    env = canopy.TrackingEnv("trajectory_handover")      # a pettingzoo.ParallelEnv
    envs = canopy.VectorEnv(8, "trajectory_handover")    # 8 episodes stepped on threads

The compiled part is canopy._canopy; everything here is thin Python over it.
"""
import os as _os

from . import _canopy

# An installed package (pip install .) carries the built-in scenarios beside this file; a build
# folder's package (PYTHONPATH=build/release/python) reads them from the source tree.
_BUILTIN = _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), "scenarios")
if _os.path.isdir(_os.path.join(_BUILTIN, "library")):
    _canopy._set_builtin_scenarios(_BUILTIN)

from ._canopy import ScenarioError, Simulation, library_scenarios  # noqa: E402
from .scenario import Scenario, load  # noqa: E402
from . import forest  # noqa: E402
from .jobs import analyze, read_record, read_run, run, sweep  # noqa: E402
from .env import TrackingEnv  # noqa: E402
from .vector import VectorEnv  # noqa: E402

__version__ = "0.1.0"

__all__ = ["ScenarioError", "Simulation", "Scenario", "load", "forest", "library_scenarios",
           "run", "sweep", "analyze", "read_run", "read_record", "TrackingEnv", "VectorEnv"]
