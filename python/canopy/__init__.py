"""canopy from Python: scenarios as objects, layout generators, stepping with your own commands.

    import canopy
    scenario = canopy.load("demo", overrides={"planner.horizon": 1})
    scenario.validate()            # raises canopy.ScenarioError naming the file and the field

The compiled part is canopy._canopy; everything here is thin Python over it.
"""
from ._canopy import ScenarioError, Simulation, library_scenarios
from .scenario import Scenario, load
from . import forest
from .jobs import analyze, read_run, run, sweep
from .env import TrackingEnv

__all__ = ["ScenarioError", "Simulation", "Scenario", "load", "forest", "library_scenarios",
           "run", "sweep", "analyze", "read_run", "TrackingEnv"]
