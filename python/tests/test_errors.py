# SPDX-License-Identifier: MIT
# The error classes against the C++ code list: every hula::Errc enumerator
# (read from src/hula/core/error.hpp, the source of the codes) has its own
# hulahoops.Error subclass, exported by the package.
import re

import pytest

import hulahoops as hh
from hulahoops import errors

from conftest import SOURCE


def errc_names():
    text = (SOURCE / "src" / "hula" / "core" / "error.hpp").read_text()
    body = re.search(r"enum class Errc[^{]*\{(.*?)\};", text, re.S).group(1)
    return re.findall(r"^\s*([A-Z]\w*)\s*[,=]", body, re.M)


def test_every_errc_has_its_own_exported_subclass():
    # checks each code of error.hpp maps to a distinct Error subclass that hulahoops exports by name
    names = errc_names()
    assert "Unsupported" in names and "HelperFailure" in names
    classes = set()
    for code in names:
        cls = errors.error_class(code)
        assert cls is not hh.Error and issubclass(cls, hh.Error), code
        assert getattr(hh, cls.__name__) is cls and cls.__name__ in hh.__all__, code
        classes.add(cls)
    assert len(classes) == len(names)


def test_unsupported_and_helper_failure_carry_code_message_where():
    # checks the two newest codes build instances with the triple the C++ translator passes
    e = errors.error_class("Unsupported")("Unsupported", "torsion: not supported by the occt backend",
                                          {"field": "torsion"})
    assert isinstance(e, hh.UnsupportedError) and e.code == "Unsupported" and e.where == {"field": "torsion"}
    e = errors.error_class("HelperFailure")("HelperFailure", "hula-exchange crashed", {"field": "path"})
    assert isinstance(e, hh.HelperFailureError) and str(e) == "HelperFailure: hula-exchange crashed"


def test_messages_speak_python(quarter_circle, tmp_path):
    # checks an out-of-domain evaluation names the keyword that allows it, not the C++ enumerator, and a
    # write to a missing folder names the argument `path`, not the CLI's --output
    with pytest.raises(hh.OutOfDomainError) as e:
        quarter_circle(1.5)
    assert 'domain="extrapolate"' in e.value.message and "::" not in str(e.value)
    with pytest.raises(hh.Error) as e:
        hh.write(quarter_circle, tmp_path / "no" / "such" / "c.json")
    assert e.value.where["field"] == "path" and "--output" not in str(e.value)
