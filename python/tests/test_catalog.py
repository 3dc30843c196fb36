"""stormer.methods, stormer.verify and methods given as data (stormer.method)."""

import json
import subprocess

import pytest

import stormer


def test_methods_lists_the_catalog_with_the_cli_keys():
    methods = stormer.methods()
    names = {m["name"] for m in methods}
    assert {"rk4", "dop853", "stormer_verlet_dkd", "boris"} <= names
    rk4 = next(m for m in methods if m["name"] == "rk4")
    assert rk4["order"] == 4 and rk4["stages"] == 4 and rk4["explicit"]
    assert set(rk4) == {
        "name", "family", "order", "stages", "explicit", "embedded_order", "fsal",
        "symplectic", "symmetric", "dense_order", "aliases",
    }
    leapfrog = next(m for m in methods if m["name"] == "stormer_verlet_dkd")
    assert leapfrog["symplectic"] and "leapfrog" in leapfrog["aliases"]


def test_verify_gives_the_report_of_the_cli_json():
    report = stormer.verify("dop853")
    assert report["name"] == "dop853"
    assert report["declared_order"] == 8
    assert report["order_conditions_ok"]
    assert report["contradictions"] == []


def test_verify_accepts_aliases_and_measures_symplecticity():
    report = stormer.verify("leapfrog")
    assert report["name"] == "stormer_verlet_dkd"
    assert report["contradictions"] == []
    assert "symplectic" in json.dumps(report)


def test_verify_unknown_method_is_a_value_error_with_suggestions():
    with pytest.raises(ValueError, match="did you mean"):
        stormer.verify("rk5")


def test_verify_of_a_pusher_is_refused_with_the_reason():
    with pytest.raises(ValueError, match="charged-particle stepper"):
        stormer.verify("boris")


def test_verify_wrong_type_is_a_type_error():
    with pytest.raises(TypeError):
        stormer.verify(4)


def test_verify_a_method_file(tmp_path):
    path = tmp_path / "heun.toml"
    path.write_text('name = "my_heun"\norder = 2\nc = ["0", "1"]\na = [["0", "0"], ["1", "0"]]\nb = ["1/2", "1/2"]\n')
    report = stormer.verify(str(path))
    assert report["name"] == "my_heun" and report["source"] == str(path)
    assert report["contradictions"] == []


def test_a_tableau_as_lists_is_checked_and_runs():
    heun = stormer.method(name="my_heun", order=2, c=[0, 1], a=[[0, 0], [1, 0]], b=["1/2", "1/2"])
    assert heun.name == "my_heun"
    assert heun.info()["order"] == 2 and heun.info()["family"] == "butcher"
    report = stormer.verify(heun)
    assert report["source"] == "Python" and report["contradictions"] == []
    result = stormer.run("kepler", method=heun, dt=0.01, t_end=1.0)
    assert result["summary"]["method"] == "my_heun"


def test_a_splitting_as_lists_and_as_toml():
    lists = stormer.method(name="my_leapfrog", order=2, drift=["1/2", "1/2"], kick=["1", "0"])
    assert lists.info()["family"] == "splitting" and lists.info()["symmetric"]
    text = 'name = "my_leapfrog"\norder = 2\ndrift = ["1/2", "1/2"]\nkick = ["1", "0"]\n'
    toml = stormer.method(text)
    assert toml.info() == lists.info()
    assert stormer.verify(toml)["contradictions"] == []


def test_a_wrong_tableau_is_refused_with_the_message_of_rust():
    with pytest.raises(ValueError, match=r"order 2 condition sum b_i c_i = 1/2 fails"):
        stormer.method(name="bad", order=2, c=[0, 1], a=[[0, 0], [1, 0]], b=[0.4, 0.6])


def test_the_same_message_as_the_cli_for_the_same_file(tmp_path):
    """The command line refuses the same coefficients as a file with the same reason."""
    path = tmp_path / "bad.toml"
    path.write_text('name = "bad"\norder = 2\nc = ["0", "1"]\na = [["0", "0"], ["1", "0"]]\nb = ["0.4", "0.6"]\n')
    with pytest.raises(ValueError) as from_file:
        stormer.verify(str(path))
    with pytest.raises(ValueError) as from_lists:
        stormer.method(name="bad", order=2, c=[0, 1], a=[[0, 0], [1, 0]], b=["0.4", "0.6"])
    reason = "order 2 condition sum b_i c_i = 1/2 fails: got 0.6"
    assert reason in str(from_file.value) and reason in str(from_lists.value)


def test_a_composition_with_a_wrong_sum_is_refused():
    with pytest.raises(ValueError, match="sum gamma_i = 1 fails"):
        stormer.method(name="x", order=2, gamma=["0.9"])


def test_method_needs_an_order_and_numbers():
    with pytest.raises(ValueError, match="declared order"):
        stormer.method(name="x", b=[1])
    with pytest.raises(TypeError, match="coefficient"):
        stormer.method(name="x", order=1, c=[0], a=[[0]], b=[None])
    with pytest.raises(TypeError):
        stormer.method(42)


def test_bad_toml_is_a_value_error():
    with pytest.raises(ValueError):
        stormer.method("name = ")


def test_method_named_resolves_catalog_names():
    m = stormer.Method.named("RK45")
    assert m.name == "dormand_prince5"
    with pytest.raises(ValueError, match="did you mean"):
        stormer.Method.named("rk-5")
