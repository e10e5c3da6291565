"""One-line TypeErrors for arguments of the wrong type.

pybind11 answers a call with arguments of the wrong type by "incompatible function arguments",
naming the private function (exactccd._exactccd._ccd_batch) and printing every argument, whole
arrays included. The public functions check their options here, and the compiled classes'
methods are wrapped so that their message names the public method, the types it was given and
the signature it takes, on one line.
"""

import functools
import numbers
import re

_PRIVATE_PREFIX = re.compile(r"\bexactccd\._exactccd\.")
_SELF = re.compile(r"^self: [\w.]+(, )?")


def _type_name(value) -> str:
    return type(value).__name__


def real(function: str, name: str, value):
    """value as a float, or a TypeError naming the function, the argument and its type."""
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        return float(value)
    raise TypeError(f"{function}(): {name} must be a real number, got {_type_name(value)} "
                    f"{value!r:.60}")


def text(function: str, name: str, value):
    if isinstance(value, str):
        return value
    raise TypeError(f"{function}(): {name} must be a str, got {_type_name(value)} {value!r:.60}")


def count_or_none(function: str, name: str, value):
    if value is None or (isinstance(value, numbers.Integral) and not isinstance(value, bool)):
        return value
    raise TypeError(f"{function}(): {name} must be an int or None, got {_type_name(value)} "
                    f"{value!r:.60}")


def _signatures(message: str):
    """The accepted signatures listed in pybind11's message, without the private names."""
    found = []
    for line in message.splitlines():
        # "    1. (self: exactccd._exactccd.Scene, *, t_max: float = 1.0) -> ..." or, for a
        # constructor, "    1. exactccd._exactccd.Scene()".
        match = re.match(r"\s+\d+\. [\w.]*(\(.*\))( -> .*)?$", line)
        if match:
            signature = _PRIVATE_PREFIX.sub("", match.group(1))
            signature = "(" + _SELF.sub("", signature[1:])
            found.append("no arguments" if signature == "()" else signature)
    return found


def _given(args, kwargs) -> str:
    parts = [_type_name(a) for a in args] + [f"{k}={_type_name(v)}" for k, v in kwargs.items()]
    return "(" + ", ".join(parts) + ")"


def one_line_type_errors(function, public_name: str, skip_self: bool = False):
    """function, with pybind11's "incompatible ... arguments" replaced by one line."""

    @functools.wraps(function)
    def checked(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except TypeError as error:
            message = str(error)
            if "incompatible function arguments" not in message and \
                    "incompatible constructor arguments" not in message:
                raise
            given = _given(args[1:] if skip_self else args, kwargs)
            takes = " or ".join(_signatures(message)) or "other arguments"
            raise TypeError(f"{public_name}(): arguments of the wrong type {given}; it takes "
                            f"{takes}") from None

    return checked


def wrap_class(cls, names=None):
    """Wraps the public methods (and the constructor) of a compiled class in place."""
    for name in names or [n for n in vars(cls) if not n.startswith("_")] + ["__init__"]:
        member = vars(cls).get(name)
        if member is None or isinstance(member, property) or not callable(member) and \
                not isinstance(member, staticmethod):
            continue
        public = f"{cls.__name__}" if name == "__init__" else f"{cls.__name__}.{name}"
        if isinstance(member, staticmethod):
            setattr(cls, name, staticmethod(one_line_type_errors(member.__func__, public)))
        else:
            setattr(cls, name, one_line_type_errors(member, public, skip_self=True))
