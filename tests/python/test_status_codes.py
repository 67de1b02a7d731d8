"""The package's STATUS_* codes are those of include/interphase.h (names and values), and the
library gives each its message."""

import re

import interphase


def header_codes(source_dir):
    text = (source_dir / "include" / "interphase.h").read_text()
    return {name: int(value) for name, value in re.findall(r"#define INTERPHASE_(STATUS_[A-Z0-9_]+) (\d+)", text)}


def test_codes_match_the_header(source_dir):
    codes = header_codes(source_dir)
    assert len(codes) > 40
    assert interphase.STATUS_CODES == codes


def test_every_code_has_the_library_message():
    assert interphase.status_message(999) == "unknown status code 999"
    for name, value in interphase.STATUS_CODES.items():
        text = interphase.status_message(value)
        assert text and not text.startswith("unknown status code"), (name, text)
    assert interphase.status_message(interphase.STATUS_BAD_SF_N) == \
        "full-crack normal separation sf_N out of range"
