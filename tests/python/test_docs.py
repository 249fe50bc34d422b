"""Every public function and class of genmod says what it does: a docstring beyond the
signature line pybind11 writes."""
import inspect
import re

import genmod as gm
from genmod import batch, gallery, procedural

SIGNATURE = re.compile(r"^(\d+\. )?\w+\(.*\)( -> .*)?$")


def text_of(doc):
    """The docstring without pybind11's signature lines and overload headers."""
    lines = [line.strip() for line in (doc or "").splitlines()]
    return " ".join(line for line in lines if line and not SIGNATURE.match(line) and line != "Overloaded function.")


def public(module):
    for name in dir(module):
        obj = getattr(module, name)
        if not name.startswith("_") and (inspect.isroutine(obj) or inspect.isclass(obj)) and \
                getattr(obj, "__module__", "genmod").startswith("genmod"):
            yield f"{module.__name__}.{name}", obj


def test_every_public_name_has_a_docstring():
    missing = [name for module in (gm, batch, gallery, procedural) for name, obj in public(module)
               if not text_of(obj.__doc__)]
    assert not missing, "no docstring: " + ", ".join(sorted(missing))
