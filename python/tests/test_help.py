"""The docstrings say what the CLI's help says: every option of `orikin fold -h` is an argument
of Pattern.fold (documented in its docstring) or named there as the CLI's own."""

import inspect
import re

import orikin
from conftest import cli

# The CLI's options and the Python names that do their work.
FOLD_OPTIONS = {
    "--fix": "fix", "--drive": "drive", "--to": "to", "--from": "from_", "--step": "step", "--lock": "lock",
    "--frame": "frame", "--solver": "solver", "--linear": "linear", "--no-collisions": "collisions",
    "--clearance": "clearance", "--percent": "percent", "--ratio": "ratio", "--symmetric": "symmetric",
    # the compliant fold (docs/compliant.md)
    "--compliant": "compliant", "--dynamic": "dynamic", "--preset": "preset", "--axial": "axial", "--facet": "facet",
    "--crease": "crease", "--damping": "damping", "--gravity": "gravity", "--steps": "steps", "--threads": "threads",
    "--all-frames": "all_frames",
}
# Options of the CLI alone, which the docstring names with their Python counterpart.
CLI_ONLY = {"--json": "--json", "-o": "-o OUT.fold", "--force": "--force", "--weld": "--weld",
            "--tolerance": "--tolerance", "--gaps": "--gaps", "--keep-collinear": "--keep-",
            "--keep-holes": "--keep-"}


def cli_options(command: str) -> set:
    out = cli(f"{command} -h").stdout
    return set(re.findall(r"(?m)^\s+(--?[a-z][a-z-]*)", out)) | set(re.findall(r"(?<![\w-])(--[a-z][a-z-]+)", out))


def test_fold_documents_every_option_of_the_cli():
    doc = inspect.getdoc(orikin.Pattern.fold)
    params = inspect.signature(orikin.Pattern.fold).parameters
    options = {o for o in cli_options("fold") if o.startswith("-")}
    unknown = options - set(FOLD_OPTIONS) - set(CLI_ONLY)
    assert not unknown, f"orikin fold has options the binding does not know: {sorted(unknown)}"
    for opt, name in FOLD_OPTIONS.items():
        assert name in params, f"{opt}: Pattern.fold has no argument {name}"
        assert re.search(rf"\b{re.escape(name)}\b", doc), f"{opt}: the docstring does not explain {name}"
    for opt, words in CLI_ONLY.items():
        assert words in doc, f"{opt}: the docstring does not say what becomes of it"
    # The paragraphs the CLI's help has: the branch, invalid folds, blocked, collisions.
    for phrase in ("loop-closure equations", "MV", "Frame A, Frame B", "self-collision", "+-180 deg",
                   "percent of the way", "rank-revealing QR", "symmetries", "bar-and-hinge", "facet hinges"):
        assert phrase in doc, phrase


def test_help_works_and_every_public_callable_has_a_docstring():
    text = []
    help_text = inspect.getdoc(orikin.Pattern.fold)
    assert help_text.startswith("Fold rigidly")
    for name in orikin.__all__:
        obj = getattr(orikin, name)
        assert inspect.getdoc(obj), name
        if inspect.isclass(obj):
            for attr, member in vars(obj).items():
                if not attr.startswith("_") and (inspect.isfunction(member) or isinstance(member, property)):
                    assert inspect.getdoc(member), f"{name}.{attr}"
                    text.append(attr)
    assert "fold" in text and "at" in text
