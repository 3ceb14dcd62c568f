"""Any ferrodyn HDF5 file read into NumPy arrays: run outputs (signals by name, units, status),
analysis files, contact and K_ij tables; pandas frames when pandas is installed."""
import numpy as np
import pytest

import ferrodyn
from conftest import SOURCE, cli, same_bits


def test_run_output_as_arrays(scenes, tmp_path):
    out = tmp_path / "run.h5"
    cli("run", scenes / "wheelset_hunting.yaml", "--t-end", "1", "-o", out, "--no-plots", "-q")
    f = ferrodyn.read(out)
    assert f.kind == "time_simulation" and f.attrs["status"] == "completed"
    assert f.time[0] == 0.0 and f.time[-1] == 1.0 and len(f.time) == 1001
    assert f.units["wheelset.y"] == "m"
    assert same_bits(f["wheelset.y"], f.datasets["/signals/wheelset.y"])
    assert "schema_version" in f["/scene/text"]  # text datasets as str


def test_tables_and_analysis_files(scenes, tmp_path):
    kij = ferrodyn.read(SOURCE / "fe_contact" / "examples" / "thesis_layer_study.h5")
    assert len(kij.datasets) > 0 and all(isinstance(k, str) for k in kij.attributes)
    cli("eig", scenes / "wheelset_hunting.yaml", "--points", "5", "-o", tmp_path / "e.h5",
        "--no-plots")
    e = ferrodyn.read(tmp_path / "e.h5")
    assert e.kind == "eigen_analysis" and e["/eigen/speed"].shape == (5,)


def test_not_hdf5_is_a_clear_error(tmp_path):
    bad = tmp_path / "x.h5"
    bad.write_text("not hdf5")
    with pytest.raises(ValueError, match="x.h5"):
        ferrodyn.read(bad)


def test_dataframes(scenes, tmp_path):
    pandas = pytest.importorskip("pandas")
    out = tmp_path / "run.h5"
    cli("run", scenes / "wheelset_hunting.yaml", "--t-end", "0.5", "-o", out, "--no-plots", "-q")
    frame = ferrodyn.read(out).to_dataframe()
    assert isinstance(frame, pandas.DataFrame) and frame.index.name == "time"
    assert same_bits(frame["wheelset.y"].to_numpy(), ferrodyn.read(out)["wheelset.y"])
    cli("sweep", scenes / "wheelset_hunting.yaml", "--speed-min", "30", "--speed-max", "40",
        "--points", "2", "--segment", "2", "--t-max", "4", "-o", tmp_path / "s.h5", "--no-plots",
        "-q")
    sweep = ferrodyn.read(tmp_path / "s.h5").to_dataframe("/sweep")
    assert list(sweep["speed"]) == [30.0, 40.0]
