"""ferrodyn: railway vehicle dynamics with a research-grade wheel-rail contact layer.

The C++ library from Python, results as NumPy arrays; SI units throughout (m, s, kg, N, rad).

    Scene, SceneError   a scene file or YAML text; any value changed by key (scene["simulation.speed"]);
                        bad input raises SceneError with file, line and key
    run(scene, ...)     time simulation -> RunResult: every signal as an array, units, metadata, status
    analysis            eigenvalues against speed, critical speed (ramp, bifurcation, eigen),
                        K_ij study, sweep (threads), assessment (EN 14363 / UIC 518 / EN 12299)
    contact             tangential and normal models on arrays of cases, profiles, contact geometry
    read(path)          any ferrodyn HDF5 file as arrays (and a pandas DataFrame when pandas is there)

Each function's docstring lists its arguments with their units (help(ferrodyn.analysis.sweep)).
"""

import sys as _sys

from . import _core
from ._core import Scene, SceneError, __version__
from ._core import analysis, contact

_sys.modules[__name__ + ".analysis"] = analysis
_sys.modules[__name__ + ".contact"] = contact

__all__ = ["Scene", "SceneError", "RunResult", "Output", "run", "read", "analysis", "contact",
           "__version__"]


def _dataframe(columns, index=None, index_name=None):
    try:
        import pandas
    except ImportError as e:
        raise ImportError("to_dataframe needs pandas (Debian: python3-pandas)") from e
    frame = pandas.DataFrame(columns, index=index)
    if index_name is not None:
        frame.index.name = index_name
    return frame


class RunResult:
    """The samples of a run and how it ended.

    time          output times [s] (NumPy array)
    signals       {name: array}: every state, then every derived signal (views of `data`)
    data          all signals, one row per signal (signals x samples; a view of the buffer the
                  run filled, no copy)
    names, units, descriptions   per signal, in `data` order; the first `state_count` are states
    status        'completed', 'interrupted' or 'solver_failure'; message says why
    t_reached [s], samples, steps, rhs_evaluations, wall_seconds [s]
    jacobians, newton_iterations, step_splits   bdf2's counts (0 for the other integrators)
    output_file   the HDF5 file written, or None
    metadata      scene, model, solver and program (as the HDF5 file's attributes)
    result["wheelset_1.y"] is result.signals["wheelset_1.y"]; str(result) is the run's summary.
    """

    def __init__(self, d):
        self.time = d["time"]
        self.data = d["data"]
        self.names = list(d["names"])
        self.units = dict(zip(self.names, d["units"]))
        self.descriptions = dict(zip(self.names, d["descriptions"]))
        self.state_count = d["state_count"]
        self.signals = {name: self.data[i] for i, name in enumerate(self.names)}
        for key in ("status", "message", "t_reached", "samples", "steps", "rhs_evaluations",
                    "jacobians", "newton_iterations", "step_splits", "wall_seconds",
                    "output_file", "metadata"):
            setattr(self, key, d[key])
        self._summary = d["summary"]

    def __getitem__(self, name):
        return self.signals[name]

    def __contains__(self, name):
        return name in self.signals

    def __str__(self):
        return self._summary

    def __repr__(self):
        return (f"<ferrodyn.RunResult {self.metadata['scene_name']}: {self.status} at "
                f"t = {self.t_reached:g} s, {self.samples} samples x {len(self.names)} signals>")

    def to_dataframe(self):
        """The signals as a pandas DataFrame indexed by time [s] (needs pandas)."""
        return _dataframe(self.signals, index=self.time, index_name="time")


def run(scene, output=None, progress=None, overwrite=False, **overrides):
    return_value = None
    try:
        return_value = RunResult(_core._run(scene, output, progress, overwrite, **overrides))
    except KeyboardInterrupt as e:
        partial = getattr(e, "result", None)
        if isinstance(partial, dict):
            e.result = RunResult(partial)
        raise
    return return_value


run.__doc__ = _core._run.__doc__.replace("-> dict", "-> RunResult", 1).replace(
    "(ferrodyn.run wraps it in a RunResult)", "as a RunResult")


class Output:
    """A ferrodyn HDF5 file read into memory.

    datasets     {path: NumPy array or text}, e.g. out.datasets["/signals/wheelset_1.y"]
    attributes   {object: {name: value}}; out.attrs is the root's (kind, status, units, ...)
    kind         the file's kind ('time_simulation', 'eigen', 'sweep', ...)
    out[name]    a dataset by path, or for a run output a signal by name (out["wheelset_1.y"])
    time, signals   for a run output: output times [s] and {name: array}; units {name: unit}
    """

    def __init__(self, path):
        self.path = str(path)
        self.datasets, self.attributes = _core._read_h5(self.path)
        self.attrs = self.attributes.get("/", {})
        self.kind = self.attrs.get("kind")
        prefix = "/signals/"
        self.signals = {k[len(prefix):]: v for k, v in self.datasets.items() if k.startswith(prefix)}
        self.time = self.datasets.get("/time")
        self.units = {k[len(prefix):]: a.get("unit") for k, a in self.attributes.items()
                      if k.startswith(prefix)}

    def __getitem__(self, name):
        if name in self.datasets:
            return self.datasets[name]
        if name in self.signals:
            return self.signals[name]
        if "/" + name in self.datasets:
            return self.datasets["/" + name]
        raise KeyError(name)

    def __repr__(self):
        return f"<ferrodyn.Output {self.path}: kind {self.kind}, {len(self.datasets)} datasets>"

    def to_dataframe(self, group=None):
        """A pandas DataFrame (needs pandas): a run output's signals indexed by time [s]; else
        the 1-D datasets of `group` (e.g. '/sweep'), one column each."""
        if group is None and self.time is not None and self.signals:
            return _dataframe(self.signals, index=self.time, index_name="time")
        group = (group or "/").rstrip("/") + "/"
        columns = {k[len(group):]: v for k, v in self.datasets.items()
                   if k.startswith(group) and "/" not in k[len(group):]
                   and getattr(v, "ndim", 0) == 1}
        return _dataframe(columns)


def read(path):
    """Reads any ferrodyn HDF5 file (run output, eigenvalue report, analyses, contact and K_ij
    tables) into an Output: every dataset as a NumPy array (text as str) and every attribute."""
    return Output(path)
