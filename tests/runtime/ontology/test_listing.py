"""``listing.walk``: ``os.walk`` for the searches of one command, each folder listed once
(``shared_listings``). Real folders in a temporary directory: the walk gives what
``os.walk`` gives (pruned folders, links to folders listed but not entered, a folder that
cannot be listed passed over), and a second walk lists nothing again, which the count of
``os.scandir`` calls shows. Runs under each robot's Python (no ezmigrate import here)."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from ezskiros_runtime.ontology import listing
from ezskiros_runtime.ontology.listing import remember, shared_listings, walk


@pytest.fixture
def tree(tmp_path: Path) -> Path:
    root = tmp_path / "repo"
    for folder in ("a/b/c", "a/.hidden", "d", "owl", "build/x"):
        (root / folder).mkdir(parents=True)
    for file in ("a/one.py", "a/b/two.py", "a/b/c/three.turtle", "d/four.launch", "owl/x.owl",
                 "top.txt", "build/x/five.py"):
        (root / file).write_text("x", encoding="utf-8")
    (root / "link_to_a").symlink_to(root / "a")  # listed, never entered
    (root / "dangling").symlink_to(root / "nowhere")
    return root


def _walked(top: Path, walker, prune: bool = False) -> list[tuple[str, list[str], list[str]]]:
    found = []
    for folder, dirs, names in walker(top):
        if prune:
            dirs[:] = [d for d in dirs if not d.startswith(".") and d != "build"]
        found.append((folder, sorted(dirs), sorted(names)))
    return sorted(found)


@pytest.mark.parametrize("prune", [False, True])
def test_the_walk_is_os_walk(tree: Path, prune: bool) -> None:
    expected = _walked(tree, os.walk, prune)
    assert _walked(tree, walk, prune) == expected  # outside: os.walk itself
    with shared_listings():
        assert _walked(tree, walk, prune) == expected
        assert _walked(tree, walk, prune) == expected  # from the listings kept
    assert any("link_to_a" in dirs for _, dirs, _ in expected)
    assert not any(folder.endswith("link_to_a") for folder, _, _ in expected)


def test_a_folder_that_cannot_be_listed_is_passed_over(tree: Path, tmp_path: Path) -> None:
    """A folder gone once its parent was listed (removed while the walk is under way, as
    the walk is lazy) cannot be listed: passed over, as ``os.walk`` passes it over."""
    def walked_while_removing(walker, root: Path) -> list[tuple[str, list[str], list[str]]]:
        found = []
        for folder, dirs, names in walker(root):
            if folder == str(root):
                shutil.rmtree(root / "d")  # listed as a folder of the root, gone now
            found.append((folder.replace(str(root), ""), sorted(dirs), sorted(names)))
        return sorted(found)

    copy = tmp_path / "copy"
    shutil.copytree(tree, copy, symlinks=True)
    expected = walked_while_removing(os.walk, copy)
    assert not any(folder.endswith("/d") for folder, _, _ in expected)
    with shared_listings():
        assert walked_while_removing(walk, tree) == expected


def _listings_noted(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """Every folder ``os.scandir`` lists from now on, by its absolute path."""
    listed: list[str] = []
    real = os.scandir

    def noted(path: str | os.PathLike[str]) -> object:
        listed.append(os.path.abspath(path))
        return real(path)

    monkeypatch.setattr(listing.os, "scandir", noted)
    return listed


def test_each_folder_is_listed_once(tree: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    listed = _listings_noted(monkeypatch)
    with shared_listings():
        first = _walked(tree, walk)
        count = len(listed)
        assert _walked(tree, walk) == first and len(listed) == count
        assert _walked(tree / "a", walk) and len(listed) == count  # a part: listed already
    assert count == len(set(listed)) == len(first)


def test_a_listing_made_by_another_search_is_taken(tree: Path,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    expected = _walked(tree, os.walk)
    with shared_listings():
        with os.scandir(tree) as entries:
            remember(tree, list(entries))
        listed = _listings_noted(monkeypatch)
        assert _walked(tree, walk) == expected
        assert str(tree) not in listed and listed  # the root from ``remember``, the rest listed
