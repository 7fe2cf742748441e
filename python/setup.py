"""Builds the Weft library with cargo and ships it inside the `weft` package.

The package talks to the library through its C ABI with ctypes, never the
Python C API, so one wheel serves every Python 3: it is tagged
py3-none-<platform>.

The Rust crate is the repository this folder sits in (the parent of
python/). `CARGO` names the cargo to run and `CARGO_TARGET_DIR` where it
builds, as for cargo itself.
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import setup
from setuptools.command.bdist_wheel import bdist_wheel
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent


def library_name():
    if sys.platform == "win32":
        return "weft.dll"
    if sys.platform == "darwin":
        return "libweft.dylib"
    return "libweft.so"


def cargo_command():
    command = [os.environ.get("CARGO", "cargo"), "build", "--release", "--lib"]
    manifest = (ROOT / "Cargo.toml").read_text(encoding="utf-8")
    features = re.search(r"^\[features\]\s*$(.*?)(?=^\[|\Z)", manifest, re.M | re.S)
    # The command line tool's dependencies sit behind a `cli` feature when
    # there is one: the library needs none of them.
    if features and re.search(r"^\s*cli\s*=", features.group(1), re.M):
        command.append("--no-default-features")
    return command


class BuildWithCargo(build_py):
    """build_py that first builds libweft with cargo and copies it into the package."""

    def run(self):
        if not (ROOT / "Cargo.toml").is_file():
            raise SystemExit(
                f"weft: {ROOT} holds no Cargo.toml; build the package from a checkout of Weft (pip install ./python)"
            )
        command = cargo_command()
        print("weft: " + " ".join(command), flush=True)
        try:
            subprocess.run(command, cwd=ROOT, check=True)
        except FileNotFoundError:
            raise SystemExit("weft: cargo was not found; install Rust (https://rustup.rs) or set CARGO") from None
        except subprocess.CalledProcessError as error:
            raise SystemExit(f"weft: cargo failed with exit status {error.returncode}") from None
        target = Path(os.environ.get("CARGO_TARGET_DIR") or ROOT / "target")
        if not target.is_absolute():
            target = ROOT / target
        built = target / "release" / library_name()
        if not built.is_file():
            raise SystemExit(f"weft: cargo finished but {built} is missing")
        super().run()
        destination = Path(self.build_lib) / "weft"
        destination.mkdir(parents=True, exist_ok=True)
        shipped = destination / library_name()
        shutil.copy2(built, shipped)
        # The release profile keeps debug info for profiling (a 30 MB
        # library); the wheel does not need it.
        strip = shutil.which("strip")
        if strip and sys.platform.startswith("linux"):
            subprocess.run([strip, "--strip-debug", str(shipped)], check=True)


class PlatformWheel(bdist_wheel):
    """Tags the wheel py3-none-<platform>: any Python 3, this platform's library."""

    def finalize_options(self):
        super().finalize_options()
        self.root_is_pure = False

    def get_tag(self):
        _, _, platform = super().get_tag()
        return "py3", "none", platform


class BinaryDistribution(Distribution):
    def has_ext_modules(self):
        return True


setup(
    cmdclass={"build_py": BuildWithCargo, "bdist_wheel": PlatformWheel},
    distclass=BinaryDistribution,
)
