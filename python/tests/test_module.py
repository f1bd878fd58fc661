"""The module exports its API only (issue 24, item 7), and messages read well."""

import pytest

import carry


def test_dir_lists_the_api_not_the_helpers_imports():
    public = {n for n in dir(carry) if not n.startswith("_")}
    for helper in ("np", "os", "csv", "tempfile", "math", "Dict", "Any", "Mapping", "annotations"):
        assert helper not in public, helper
    assert public == set(carry.__all__)
    for name in carry.__all__:
        assert callable(getattr(carry, name)), name


def test_a_scalar_call_names_no_empty_row():
    with pytest.raises(carry.ShotError) as e:
        carry.shot(club_speed=-1, raise_on_error=True)
    assert "row ()" not in str(e.value)
    assert str(e.value) == e.value.message
    assert e.value.index == ()


def test_an_array_call_names_the_row():
    with pytest.raises(carry.ShotError, match=r"row \(1,\): "):
        carry.shot(club_speed=[40.0, -1.0], raise_on_error=True)


def test_an_option_an_analysis_replaces_is_a_warning():
    with pytest.warns(UserWarning, match="--attack-angle is ignored"):
        carry.optimize(club="7iron", club_speed=40, attack_angle=-2,
                       attack_angle_range=(-5, 1))
    held = carry.optimize(club="7iron", club_speed=40, attack_angle=-2)
    assert held["attack_angle_deg"] == -2.0
