"""PEP 517 build backend of the orikin package: setuptools', needing nothing from an index.

pyproject.toml requires nothing, so pip's isolated build environment installs nothing (the
machine may be offline), and this backend takes setuptools and wheel from the interpreter's own
site-packages, which isolation hides from the build (Debian: python3-setuptools, python3-wheel;
a virtualenv's own setuptools first). With setuptools importable it is setuptools.build_meta.
"""

import os
import site
import sys


def _find(module: str) -> None:
    """Make module importable from the running interpreter's site-packages, if it is there."""
    try:
        __import__(module)
        return
    except ImportError:
        pass
    prefixes = [p for p in (sys.prefix, sys.base_prefix) if p]
    for d in site.getsitepackages(prefixes):
        if os.path.isdir(os.path.join(d, module)) and d not in sys.path:
            sys.path.append(d)
            return


_find("setuptools")
_find("wheel")
import setuptools.build_meta as _sb  # noqa: E402

build_wheel = _sb.build_wheel
build_sdist = _sb.build_sdist
prepare_metadata_for_build_wheel = _sb.prepare_metadata_for_build_wheel


def get_requires_for_build_wheel(config_settings=None):
    return []  # setuptools and wheel are the interpreter's (above)


def get_requires_for_build_sdist(config_settings=None):
    return []
