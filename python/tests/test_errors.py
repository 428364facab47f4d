"""Errors are exceptions carrying the library's one-line message — the very line the CLI prints
after 'orikin CMD: ' — and where it points (status, FOLD index, field, line, column, option)."""

import pytest

import orikin
from conftest import cli, cli_error, open_corner, repo


@pytest.mark.parametrize("path", ["nope.fold", "tests/data/bad-json.fold", "tests/data/bad-index.fold",
                                  "tests/data/bad-crossing-extra-field.fold", "tests/data/bad-overlap-mv.fold",
                                  "tests/data/bad-type.fold",
                                  "tests/data/bad-fold-angle.fold", "tests/data/bad-zero-length.fold"])
def test_a_bad_file_raises_the_clis_message(path, monkeypatch):
    want = cli_error(f"check {path}")
    monkeypatch.chdir(repo("."))  # the same path as the CLI was given
    with pytest.raises(orikin.InputError) as e:
        orikin.Pattern.load(path)
    assert str(e.value) == want
    assert isinstance(e.value, ValueError) and isinstance(e.value, orikin.Error)


def test_crossing_or_overlapping_creases_are_planarised_as_the_cli_does():
    path = repo("tests/data/layers/overlapping-creases.fold")
    with pytest.warns(UserWarning, match="its edges cross or overlap: planarised 8 edges into 9"):
        p = orikin.Pattern.load(path)
    assert p.edge_count == 9 and p.face_count == 2
    r = cli(f"info {path}")
    assert r.returncode == 0 and "planarised 8 edges into 9" in r.stderr


def test_the_exception_says_where():
    with pytest.raises(orikin.InputError) as e:
        orikin.Pattern.load(repo("tests/data/bad-index.fold"))
    assert e.value.status == "ERR_RANGE" and e.value.field == "edges_vertices" and isinstance(e.value.element, int)
    assert str(e.value).endswith(e.value.reason)
    with pytest.raises(orikin.InputError) as e:
        orikin.Pattern.load(repo("tests/data/bad-json.fold"))
    assert e.value.status == "ERR_PARSE" and e.value.line >= 1 and e.value.column >= 1 and e.value.element is None


@pytest.mark.parametrize("args,kw", [
    ("--fix 99 --drive 12 --to 90", dict(fix=99, drive=12, to=90)),
    ("--fix 4 --drive 99 --to 90", dict(fix=4, drive=99, to=90)),
    ("--fix 4 --drive 12 --lock 11,42 --to 90", dict(fix=4, drive=12, lock=[11, 42], to=90)),
    ("--fix Obj9 --drive 12 --to 90", dict(fix="Obj9", drive=12, to=90)),
    ("--fix @5,5 --drive 12 --to 90", dict(fix=(5.0, 5.0), drive=12, to=90)),
    ("--fix 4 --drive @9,9 --to 90", dict(fix=4, drive="@9,9", to=90)),
    ("--fix @1,0.5 --drive 12 --to 90", dict(fix=(1.0, 0.5), drive=12, to=90)),
])
def test_a_bad_index_raises_the_clis_message(args, kw, monkeypatch):
    want = cli_error(f"fold examples/patterns/open-corner.fold {args}")
    monkeypatch.chdir(repo("."))
    p = orikin.Pattern.load("examples/patterns/open-corner.fold")
    with pytest.raises(orikin.InputError) as e:
        p.fold(**kw)
    assert str(e.value) == want
    assert e.value.option in ("--fix", "--drive", "--lock") and e.value.option in want


@pytest.mark.parametrize("args,kw", [
    ("--fix 4 --drive 12 --to 200", dict(fix=4, drive=12, to=200)),
    ("--fix 4 --drive 12 --to 90 --step 0", dict(fix=4, drive=12, to=90, step=0)),
    ("--fix 4 --percent 120", dict(fix=4, percent=120)),
    ("--fix 4 --percent 50 --drive 12", dict(fix=4, percent=50, drive=12)),
    ("--fix 4 --drive 12,6 --to 90", dict(fix=4, drive=[12, 6], to=90)),
])
def test_usage_errors_say_what_the_cli_says(args, kw):
    r = cli_error(f"fold examples/patterns/open-corner.fold {args}")
    with pytest.raises(orikin.InputError) as e:
        open_corner().fold(**kw)
    assert str(e.value) == r


def test_a_library_error_during_a_fold_names_the_file_and_index():
    p = orikin.Pattern.load(repo("tests/data/waterbomb-base.fold"))
    with pytest.raises(orikin.InputError) as e:
        p.fold(fix=0, drive=[0, 1], to=[90, 90])
    assert e.value.element == 0 and str(e.value).startswith(p.source + ": edges_vertices 0: ")


def test_arrays_are_validated_like_a_file():
    v = [(0, 0), (1, 0), (1, 1), (0, 1)]
    e = [(0, 1), (1, 2), (2, 3), (3, 7)]
    with pytest.raises(orikin.InputError) as err:
        orikin.Pattern.from_arrays(v, e, "BBBB")
    assert err.value.element == 3 and err.value.field == "edges_vertices"
    assert str(err.value).startswith("<arrays>: edges_vertices 3: ")
    with pytest.raises(orikin.InputError) as err:
        orikin.Pattern.from_arrays(v, [(0, 1), (1, 2), (2, 3), (3, 0)], "BBBX")
    assert err.value.option == "assignment"
    with pytest.raises(ValueError, match="3 letters for 4 edges"):
        orikin.Pattern.from_arrays(v, [(0, 1), (1, 2), (2, 3), (3, 0)], "BBB")
    with pytest.raises(ValueError, match="4 entries, got 2"):
        orikin.Pattern.from_arrays(v, [(0, 1), (1, 2), (2, 3), (3, 0)], "BBBB", fold_angles=[0, 0])


def test_a_from_fold_dict_error_has_the_line_of_the_json():
    with pytest.raises(orikin.InputError) as e:
        orikin.Pattern.from_fold('{"vertices_coords": [[0, 0], [1, 0]], "edges_vertices": [[0, 9]]}')
    assert str(e.value).startswith("<fold>: edges_vertices 0: ")
    with pytest.raises(orikin.InputError) as e:
        orikin.Pattern.from_fold('{"vertices_coords": [[0, 0]')
    assert e.value.line == 1 and e.value.status == "ERR_PARSE"


def test_a_bad_sequence_file_raises_the_clis_message(monkeypatch, tmp_path):
    bad = tmp_path / "bad.seq.json"
    bad.write_text('{"pattern": "x.fold", "folds": [')
    monkeypatch.chdir(repo("."))
    for path in ("nope.seq.json", str(bad)):
        want = cli_error(f"sequence {path}")
        with pytest.raises(orikin.InputError) as e:
            orikin.Record.load(path)
        assert str(e.value) == want
