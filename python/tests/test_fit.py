"""`carry.fit` against `carry fit --json` on the measured TrackMan data."""

import json
import subprocess

import numpy as np
import pytest

import carry

CONDITIONS = dict(temperature=21.1, humidity=50, pressure=101325)


def cli_fit(cli, path, *extra):
    args = [cli, "fit", "--json", "--no-progress", "--input", str(path)]
    args += [f"--{k}={v}" for k, v in CONDITIONS.items()]
    out = subprocess.run(args + list(extra), check=True, capture_output=True, text=True).stdout
    return json.loads(out)


@pytest.fixture(scope="module")
def trackman(shared_data):
    return shared_data / "trackman_tour_2023.csv"


def test_fit_dataframe_matches_cli(cli, trackman):
    pd = pytest.importorskip("pandas")
    expected = cli_fit(cli, trackman)
    got = carry.fit(pd.read_csv(trackman), **CONDITIONS)
    assert got["family"] == expected["family"]
    assert got["rows"] == expected["rows"]
    assert got["coefficients"].keys() == expected["coefficients"].keys()
    for k, v in expected["coefficients"].items():
        assert got["coefficients"][k] == pytest.approx(v, rel=1e-12), k
    for key in ("summary", "loo_summary"):
        assert json.dumps(got["fit"][key]) == json.dumps(expected["fit"][key]) or got["fit"][key] == pytest.approx(
            expected["fit"][key]
        )
    assert [r["label"] for r in got["fit"]["rows"]] == [r["label"] for r in expected["fit"]["rows"]]
    assert got["fit"]["rows"][0]["loo_predicted"] is not None


def test_fit_accepts_dicts_structured_arrays_and_paths(trackman):
    pd = pytest.importorskip("pandas")
    df = pd.read_csv(trackman)
    kw = dict(cross_validation=False, **CONDITIONS)
    from_df = carry.fit(df, **kw)
    from_dict = carry.fit({c: df[c].to_numpy() for c in df.columns}, **kw)
    from_path = carry.fit(str(trackman), **kw)
    numeric = df.select_dtypes("number")
    structured = np.rec.fromarrays([numeric[c].to_numpy() for c in numeric.columns], names=list(numeric.columns))
    from_struct = carry.fit(structured, **kw)
    for other in (from_dict, from_path, from_struct):
        assert other["coefficients"] == from_df["coefficients"]


def test_fit_bad_arguments_raise_value_error(trackman):
    with pytest.raises(ValueError, match="family"):
        carry.fit(str(trackman), family="cubic")
    with pytest.raises(ValueError, match="input"):
        carry.fit({"ball_speed": [70.0]})
    with pytest.raises(ValueError, match="data"):
        carry.fit(42)


def test_fit_also_joins_tables_and_checks_the_table_weight(cli, shared_data):
    """`also` is `carry fit --also`: the compliant family on club_delivery.csv plus the 2010
    driver chart (a path and a DataFrame give the same fit, equal to the CLI's), and a bad
    `table_weight` or `also` item is a ValueError naming it."""
    pd = pytest.importorskip("pandas")
    delivery = shared_data / "club_delivery.csv"
    chart = shared_data / "trackman_driver_optimizer_2010.csv"
    kw = dict(family="compliant", cross_validation=False)
    from_path = carry.fit(str(delivery), also=[chart], **kw)
    from_frame = carry.fit(str(delivery), also=pd.read_csv(chart), **kw)
    assert from_path["rows"] == 41
    assert from_frame["rows"] == 41
    assert from_frame["coefficients"] == pytest.approx(from_path["coefficients"], rel=1e-12)
    args = [cli, "fit", "--json", "--no-progress", "--family", "compliant", "--input", str(delivery)]
    out = subprocess.run(args + ["--also", str(chart), "--no-cross-validation"], check=True, capture_output=True, text=True)
    expected = json.loads(out.stdout)
    for k, v in expected["coefficients"].items():
        assert from_path["coefficients"][k] == pytest.approx(v, rel=1e-12), k
    with pytest.raises(ValueError, match="table_weight"):
        carry.fit(str(delivery), also=[chart], table_weight="heavy", **kw)
    with pytest.raises(ValueError, match=r"also\[0\]"):
        carry.fit(str(delivery), also=[42], **kw)
