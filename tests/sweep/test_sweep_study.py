"""Study definitions: grids, samples, chunk layout, study files and their errors."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab.sweep import INPUTS, LogNormal, Normal, Sample, Study, Uniform, load_study
from impactlab.sweep.dimensions import chunk_shape
from impactlab.sweep.distributions import distribution_from_dict, uniforms

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _grid_study(**kw):
    base = dict(
        name="g",
        grid={
            "angle": np.radians([10.0, 20.0, 30.0]),
            "mu": [0.0, 0.1, 0.2, 0.3],
            "law": ["ghaednia", "hertz"],
        },
        fixed={"vy": -1.41},
        chunk_size=5,
    )
    base.update(kw)
    return Study(**base)


def test_grid_layout_and_cases_cover_every_point_once() -> None:
    s = _grid_study()
    lay = s.layout
    assert lay.dims == ("angle", "mu", "law")
    assert lay.shape == (3, 4, 2)
    assert lay.chunks[2] == 1  # one law per chunk (one engine call)
    seen = set()
    for k in range(lay.n_chunks):
        num, cat, bshape = s.chunk_cases(k)
        block = lay.block(k)
        assert int(np.prod(bshape)) == lay.block_size(k) == len(num["angle"])
        law_idx = block[2].start
        assert cat["law"] == ["ghaednia", "hertz"][law_idx]
        # C-order over the block
        idx = np.indices(bshape).reshape(len(bshape), -1)
        for i in range(len(num["angle"])):
            a = block[0].start + idx[0, i]
            m = block[1].start + idx[1, i]
            assert num["angle"][i] == s.axes[0].values[a]
            assert num["mu"][i] == s.axes[1].values[m]
            seen.add((a, m, law_idx))
        assert np.all(num["vy"] == -1.41)
        assert np.all(num["vx"] == 0.0)  # default
        assert np.all(np.isnan(num["flat_E"]))  # preset value
    assert len(seen) == lay.n_cases == 24


@given(
    shape=st.lists(st.integers(1, 40), min_size=1, max_size=4),
    target=st.integers(1, 5000),
    data=st.data(),
)
@settings(max_examples=60, deadline=None)
def test_chunk_shape_tiles_the_array(shape, target, data) -> None:
    cat = data.draw(st.lists(st.booleans(), min_size=len(shape), max_size=len(shape)))
    c = chunk_shape(shape, cat, target)
    assert all(1 <= ci <= ni for ci, ni in zip(c, shape, strict=True))
    assert all(ci == 1 for ci, k in zip(c, cat, strict=True) if k)
    # at most max(target, one full trailing line) cases per chunk
    assert int(np.prod(c)) <= max(target, 1)


def test_sample_draws_do_not_depend_on_chunking() -> None:
    dists = {"angle": Normal(math.radians(45), math.radians(1)), "mu": Uniform(0.1, 0.3)}
    a = Study(
        name="a", sample=Sample(size=1000, seed=7, inputs=dists), fixed={"vy": -2.0}, chunk_size=64
    )
    b = Study(
        name="b", sample=Sample(size=1000, seed=7, inputs=dists), fixed={"vy": -2.0}, chunk_size=333
    )

    def gather(s):
        parts = [s.chunk_cases(k)[0] for k in range(s.layout.n_chunks)]
        return {n: np.concatenate([p[n] for p in parts]) for n in ("angle", "mu")}

    ga, gb = gather(a), gather(b)
    np.testing.assert_array_equal(ga["angle"], gb["angle"])
    np.testing.assert_array_equal(ga["mu"], gb["mu"])
    # another seed gives other draws; the inputs' streams are independent
    c = Study(name="c", sample=Sample(size=1000, seed=8, inputs=dists), fixed={"vy": -2.0})
    assert not np.array_equal(gather(c)["mu"], ga["mu"])
    assert abs(np.corrcoef(ga["angle"], ga["mu"])[0, 1]) < 0.1


def test_uniform_stream_is_uniform() -> None:
    u = uniforms(1, "x", 0, 200_000)
    assert 0.0 < u.min() and u.max() < 1.0
    assert abs(u.mean() - 0.5) < 0.005
    assert abs(u.var() - 1 / 12) < 0.002
    # a slice of the stream equals the stream's slice
    np.testing.assert_array_equal(uniforms(1, "x", 1000, 1010), u[1000:1010])


def test_distribution_moments_and_truncation() -> None:
    u = uniforms(3, "d", 0, 400_000)
    x = Normal(2.0, 0.5).ppf(u)
    assert abs(x.mean() - 2.0) < 0.005 and abs(x.std() - 0.5) < 0.005
    t = Normal(0.0, 1.0, low=0.0).ppf(u)  # half-normal: mean sqrt(2/pi)
    assert t.min() >= 0.0 and abs(t.mean() - math.sqrt(2 / math.pi)) < 0.005
    far = Normal(0.0, 1.0, low=6.0, high=7.0).ppf(u)  # deep tail stays inside its bounds
    assert far.min() >= 6.0 and far.max() <= 7.0 and np.isfinite(far).all()
    ln = LogNormal.from_mean_std(305e6, 15e6).ppf(u)
    assert abs(ln.mean() / 305e6 - 1) < 0.002 and abs(ln.std() / 15e6 - 1) < 0.02
    assert abs(np.median(LogNormal(3.0, 0.1).ppf(u)) - 3.0) < 0.01


@pytest.mark.parametrize(
    ("spec", "message"),
    [
        ({"dist": "gauss", "mean": 1, "std": 1}, "unknown distribution 'gauss'"),
        ({"mean": 1, "std": 1}, "missing 'dist'"),
        ({"dist": "normal", "mean": 1}, "needs 'std'"),
        ({"dist": "normal", "mean": 1, "std": -1}, "std must be > 0"),
        ({"dist": "uniform", "low": 2, "high": 1}, "low < high"),
        ({"dist": "normal", "mean": 0, "std": 1, "low": 100, "high": 101}, "no probability"),
        ({"dist": "truncnormal", "mean": 0, "std": 1}, "low and/or high"),
        ({"dist": "lognormal", "median": 1}, "needs 'sigma'"),
        ({"dist": "uniform", "low": 0, "high": 1, "sd": 1}, "unknown parameter"),
    ],
)
def test_bad_distributions(spec, message) -> None:
    with pytest.raises(ValueError, match=message):
        distribution_from_dict(spec, lambda v, k: float(v), "mu")


def test_a_bad_parameter_of_an_angle_names_its_si_unit() -> None:
    """The parameters are converted to SI before they are checked: the message says in what."""
    spec = {"dist": "normal", "mean": "20 deg", "std": "-1 deg"}
    with pytest.raises(ValueError, match=r"std must be > 0, got -0.01745\d* \(in rad, the "):
        distribution_from_dict(spec, lambda v, k: math.radians(float(v.split()[0])), "angle")


def test_study_table_units_and_round_trip() -> None:
    s = Study.from_dict(
        {
            "study": {"name": "x", "chunk_size": 100},
            "fixed": {
                "vy": "-1410 mm/s",
                "flat_yield_strength": "305 MPa",
                "flat_nu": 0.3,
                "law": "hertz",
            },
            "grid": {
                "angle": {"start": 10, "stop": 30, "num": 3, "unit": "deg"},
                "mu": {"start": 0.0, "stop": 0.2, "step": 0.1},
                "flat_E": {"values": [190, 210], "unit": "GPa"},
            },
            "sample": {
                "size": 10,
                "seed": 3,
                "vx": {"dist": "normal", "mean": "0 m/s", "std": "20 mm/s"},
            },
            "outputs": {"keep": ["e", "L_s", "T"]},
        }
    )
    assert s.fixed["vy"] == pytest.approx(-1.41)
    assert s.fixed["flat_yield_strength"] == pytest.approx(305e6)
    assert s.fixed["flat_material"] == "custom"  # a material by values, never "aisi-1010"
    np.testing.assert_allclose(s.axes[0].values, np.radians([10, 20, 30]))  # unit = "deg"
    np.testing.assert_allclose(s.axes[1].values, [0.0, 0.1, 0.2])
    assert s.axes[2].values == (190e9, 210e9)
    assert s.sample is not None and s.sample.inputs["vx"].std == pytest.approx(0.02)
    assert s.outputs == ("e", "sliding_length", "duration")
    assert s.layout.dims == ("angle", "mu", "flat_E", "sample")
    again = Study.from_dict(s.to_dict())
    assert again.to_json() == s.to_json()
    assert again.hash() == s.hash()
    # the hash follows what changes the results, not the description
    assert (
        Study.from_dict({**s.to_dict(), "fixed": {**s.to_dict()["fixed"], "vy": -1.0}}).hash()
        != s.hash()
    )


@pytest.mark.parametrize(
    ("table", "message"),
    [
        (
            {"grid": {"angel": [1, 2]}, "fixed": {"vy": -1, "mu": 0.1}},
            "unknown input 'angel'; known inputs: angle, vx",
        ),
        (
            {"fixed": {"vy": -1, "mu": 0.1, "angle": "20 deg"}},
            "needs a \\[grid\\] or a \\[sample\\]",
        ),
        ({"grid": {"angle": ["10 deg"]}, "fixed": {"vy": -1}}, r"\['mu'\] have no value"),
        (
            {"grid": {"angle": ["10 deg"], "mu": [0.1]}, "fixed": {"vy": -1, "mu": 0.2}},
            "'mu' is set twice",
        ),
        (
            {"grid": {"angle": ["10 deg"], "mu": [0.1]}, "fixed": {"vy": "fast"}},
            "cannot parse 'fast'",
        ),
        (
            {"grid": {"angle": ["10 deg"], "mu": [0.1]}, "fixed": {"vy": "2 kg"}},
            "has the wrong dimension; expected a quantity convertible to m/s",
        ),
        (
            {
                "grid": {"angle": {"start": 1, "stop": 2, "unit": "deg"}, "mu": [0.1]},
                "fixed": {"vy": -1},
            },
            "exactly one of 'num' and 'step'",
        ),
        (
            {"grid": {"angle": ["10 deg", "10 deg"], "mu": [0.1]}, "fixed": {"vy": -1}},
            "repeated values",
        ),
        (
            {"grid": {"angle": ["10 deg"], "mu": [0.1]}, "fixed": {"vy": -1}, "plots": {}},
            "unknown table",
        ),
        (
            {
                "sample": {"size": 10, "law": {"dist": "uniform"}},
                "fixed": {"vy": -1},
                "grid": {"angle": ["1 deg"], "mu": [0.1]},
            },
            "category",
        ),
        (
            {
                "sample": {"seed": 1, "mu": {"dist": "uniform", "low": 0, "high": 1}},
                "fixed": {"vy": -1, "angle": "10 deg"},
            },
            "needs 'size'",
        ),
        (
            {"grid": {"angle": ["10 deg"], "mu": [0.1]}, "fixed": {"vy": -1}, "engine": {"tol": 1}},
            "unknown key",
        ),
        (
            {
                "grid": {"angle": ["10 deg"], "mu": [0.1]},
                "fixed": {"vy": -1},
                "study": {"chunk_size": 0},
            },
            "chunk_size must be",
        ),
    ],
)
def test_study_file_errors_name_the_problem(table, message) -> None:
    with pytest.raises(ValueError, match=message):
        Study.from_dict(table)


def test_log_spacing_takes_either_sign() -> None:
    def axis(name: str, start: float, stop: float) -> np.ndarray:
        grid = {name: {"start": start, "stop": stop, "num": 4, "spacing": "log"}}
        fixed = {"angle": "20 deg", "mu": 0.2, "vy": -1.0}
        s = Study.from_dict({"grid": grid, "fixed": {k: v for k, v in fixed.items() if k != name}})
        return np.asarray(s.axes[0].values)

    np.testing.assert_allclose(axis("vy", -4.0, -0.5), -np.geomspace(4.0, 0.5, 4))
    np.testing.assert_allclose(axis("mu", 0.05, 0.4), np.geomspace(0.05, 0.4, 4))
    for start, stop in ((-4.0, 0.5), (0.0, 1.0)):
        with pytest.raises(ValueError, match="log spacing needs start and stop of one sign"):
            axis("vy", start, stop)


def test_study_file_reading(tmp_path) -> None:
    p = tmp_path / "s.toml"
    p.write_text(
        '[fixed]\nvy = "-1.41 m/s"\nmu = 0.2\n[grid]\nangle = ["20 deg", "45 deg", "70 deg"]\n'
    )
    s = load_study(p)
    assert s.name == "s" and s.layout.shape == (3,)
    bad = tmp_path / "bad.toml"
    bad.write_text("[grid\n")
    with pytest.raises(ValueError, match="not valid TOML"):
        load_study(bad)
    with pytest.raises(ValueError, match="does not exist"):
        load_study(tmp_path / "missing.toml")


def test_example_study_files_parse() -> None:
    files = sorted(EXAMPLES.glob("study-*.toml"))
    assert files, "examples/study-*.toml missing"
    for f in files:
        s = load_study(f)
        assert s.n_cases >= 1
        for name in s.varying():
            assert name in INPUTS


def test_every_input_is_documented() -> None:
    text = (EXAMPLES.parent / "docs" / "sweep.md").read_text()
    missing = [n for n in INPUTS if f"`{n}`" not in text]
    assert not missing, f"docs/sweep.md does not document {missing}"
