import os
import shutil
from pathlib import Path

import numpy as np
import pytest

import weft

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def cli():
    """The `weft` command built from this checkout (python/test.sh builds it)."""
    target = Path(os.environ.get("CARGO_TARGET_DIR") or ROOT / "target")
    if not target.is_absolute():
        target = ROOT / target
    path = os.environ.get("WEFT_CLI") or target / "release" / "weft"
    if not Path(path).is_file():
        pytest.fail(f"the weft command is not built at {path}: run python/test.sh, or cargo build --release")
    return str(path)


@pytest.fixture
def header():
    return (ROOT / "include" / "weft.h").read_text(encoding="utf-8")


def random_cage(seed=1, u=6, v=5):
    """An open, wavy quad grid with random heights: a mesh with a boundary,
    interior and corner vertices, and coordinates no rounding hides."""
    rng = np.random.default_rng(seed)
    grid = weft.plane_grid(3.0, 2.0, u, v)
    vertices = np.array(grid.vertices)
    vertices[:, 2] = rng.uniform(-0.4, 0.4, len(vertices))
    vertices[:, :2] += rng.uniform(-0.05, 0.05, (len(vertices), 2))
    return weft.Mesh(vertices, grid.faces)


@pytest.fixture
def cage():
    return random_cage()


@pytest.fixture
def mixed():
    """A triangle, a quad and a pentagon sharing edges."""
    vertices = [[0, 0, 0], [1, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [0, 1, 0], [1.5, 1.8, 0.2]]
    faces = [[0, 1, 4, 5], [1, 2, 3, 4], [4, 3, 6], [5, 4, 6]]
    return weft.Mesh(vertices, faces)


@pytest.fixture
def pentagon_mesh():
    vertices = [[np.cos(a), np.sin(a), 0.0] for a in np.linspace(0, 2 * np.pi, 6)[:-1]] + [[0, 0, 1.0]]
    faces = [[0, 1, 2, 3, 4], [0, 5, 1], [1, 5, 2]]
    return weft.Mesh(vertices, faces)


def same_bits(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and a.tobytes() == b.tobytes()


@pytest.fixture
def tmp(tmp_path):
    return tmp_path


def which(name):
    return shutil.which(name)
