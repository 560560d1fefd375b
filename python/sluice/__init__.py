"""sluice from Python: read a case, step its simulation, read its fields, probes and loads.

    import sluice
    case = sluice.Case.from_yaml("cases/dam_break_2d.yaml", set={"end_time": 0.2})
    sim = sluice.Simulation(case, out="out/dam_break", threads=2)
    sim.run(every=0.05, callback=lambda s: print(s.time, s.probes()))
    positions = sim.fields(copy=True)["position"]
    rows = sluice.sweep("cases/dam_break_2d.yaml", set={"spacing": [0.02, 0.01]})

docs/python.md describes every call.
"""
from ._sluice import (Case, DivergenceError, InputError, Simulation, __version__, compare,
                      source_revision, sweep)

__all__ = ["Case", "DivergenceError", "InputError", "Simulation", "__version__", "compare",
           "source_revision", "sweep"]
