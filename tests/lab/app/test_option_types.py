"""lab/app/option_types.py: the numeric option types give the value, or one short reason that
repeats what was typed (argparse turns it into one line and exit status 2)."""
from __future__ import annotations

import argparse

import pytest

from lab.app.option_types import image_size, number, seconds, whole


def test_whole_numbers_within_their_bounds_are_read():
    assert whole(1)("3") == 3
    assert whole(0, 65535)("0") == 0 and whole(0, 65535)("65535") == 65535


@pytest.mark.parametrize("kind,text,reason", [
    (whole(1), "x", "expected a whole number, got 'x'"),
    (whole(1), "2.5", "expected a whole number, got '2.5'"),
    (whole(1), "0", "must be at least 1, got '0'"),
    (whole(0, 65535, "a port number", " (0: any free one)"), "70000",
     "expected a port number from 0 to 65535 (0: any free one), got '70000'"),
    (whole(0, 65535, "a port number"), "-1", "expected a port number from 0 to 65535, got '-1'"),
    (number(0.0), "nan", "must be a finite number, got 'nan'"),
    (number(0.0), "inf", "must be a finite number, got 'inf'"),
    (number(0.0), "-0.5", "must be at least 0, got '-0.5'"),
    (number(0.0, above=True, what="seconds", unit=" seconds"), "0", "must be more than 0 seconds, got '0'"),
    (number(0.0, what="seconds"), "soon", "expected seconds, got 'soon'"),
    (image_size, "512", "expected WIDTHxHEIGHT such as 512x384, got '512'"),
    (image_size, "0x10", "width and height must be at least 1, got '0x10'"),
])
def test_a_bad_value_gives_one_reason(kind, text, reason):
    with pytest.raises(argparse.ArgumentTypeError) as caught:
        kind(text)
    assert str(caught.value) == reason


def test_numbers_and_sizes_are_read():
    assert number(0.0)("0") == 0.0 and number(0.0, above=True)("0.25") == 0.25
    assert image_size("512X384") == (512, 384)


@pytest.mark.parametrize("text,reason", [("0", "must be more than 0 seconds, got '0'"),
                                         ("1e300", "must be at most 1e+06 seconds, got '1e300'"),
                                         ("soon", "expected seconds, got 'soon'")])
def test_a_time_limit_is_more_than_0_and_at_most_a_million_seconds(text, reason):
    assert seconds("2.5") == 2.5
    with pytest.raises(argparse.ArgumentTypeError) as caught:
        seconds(text)
    assert str(caught.value) == reason
