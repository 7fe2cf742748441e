#!/usr/bin/env python3
"""Runs grasshopper/package.sh with stand-in binaries (the Linux library for
weft.dll and libweft.dylib) and checks the three Yak layouts: every file at
its place with the bytes it was given, nothing else, a valid manifest.yml in
each, and the distributions named in the output. Also checks that the
project references RhinoCommon and Grasshopper 7.x for net48 and 8.x for
net7.0 with literal versions, and that the release workflow is in place.

usage: check_packages.py <grasshopper folder> <.gha> <Weft.Interop.dll> <native library> <output folder>
"""
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

failures = []


def expect(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


def read_manifest(path):
    """The subset of YAML a Yak manifest uses: `key: value`, `key:` then
    `  - item` lines, and `key: >` folded text. Raises ValueError on anything else."""
    data, key = {}, None
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        item = re.match(r"  - (.+)$", line)
        folded = re.match(r"  (\S.*)$", line)
        pair = re.match(r"([a-z_]+):(?: (.*))?$", line)
        if item and isinstance(data.get(key), list):
            data[key].append(item.group(1).strip())
        elif folded and isinstance(data.get(key), str) and data.get("_folded") == key:
            data[key] = (data[key] + " " + folded.group(1)).strip()
        elif pair:
            key, value = pair.group(1), (pair.group(2) or "").strip()
            if value == ">":
                data[key], data["_folded"] = "", key
            elif value:
                data[key] = value
            else:
                data[key] = []
        else:
            raise ValueError(f"{path}:{number}: not a manifest line: {line!r}")
    data.pop("_folded", None)
    return data


def check_manifest(folder, version):
    path = folder / "manifest.yml"
    try:
        m = read_manifest(path)
    except (OSError, ValueError) as e:
        expect(False, f"{path} reads: {e}")
        return
    expect(re.fullmatch(r"[a-z][a-z0-9_-]*", m.get("name", "")) is not None, f"{folder.name}: name {m.get('name')!r} is a Yak package name")
    expect(m.get("version") == version, f"{folder.name}: version {m.get('version')!r} is {version}")
    expect(isinstance(m.get("authors"), list) and len(m["authors"]) > 0, f"{folder.name}: authors listed")
    expect(isinstance(m.get("description"), str) and len(m["description"]) > 20, f"{folder.name}: a description")
    expect(m.get("url", "").startswith("https://"), f"{folder.name}: url")
    expect((folder / m.get("icon", "missing")).is_file(), f"{folder.name}: the icon {m.get('icon')} is in the folder")


def main():
    here, gha, interop, native, out = (Path(a) for a in sys.argv[1:6])
    if out.exists():
        shutil.rmtree(out)
    build = out / "inputs"
    for framework in ("net48", "net7.0"):
        (build / framework).mkdir(parents=True)
        shutil.copy(gha, build / framework / "Weft.Grasshopper.gha")
        shutil.copy(interop, build / framework / "Weft.Interop.dll")
    # Distinct bytes per input, so a file copied to the wrong place is caught.
    (build / "net7.0" / "Weft.Grasshopper.gha").write_bytes(gha.read_bytes() + b"net7.0")
    stand_ins = {}
    for name in ("win-x64", "win-arm64", "osx"):
        stand_ins[name] = build / f"{name}-{native.name}"
        stand_ins[name].write_bytes(native.read_bytes() + name.encode())
    version = "1.2.3"
    run = subprocess.run(
        [str(here / "package.sh"), "--net48", str(build / "net48"), "--net7", str(build / "net7.0"),
         "--win-x64", str(stand_ins["win-x64"]), "--win-arm64", str(stand_ins["win-arm64"]),
         "--osx", str(stand_ins["osx"]), "--out", str(out), "--version", version],
        capture_output=True, text=True)
    print(run.stdout, end="")
    expect(run.returncode == 0, "package.sh succeeds" + (": " + run.stderr.strip() if run.returncode else ""))
    for distribution in (f"weft-{version}-rh7_0-win.yak", f"weft-{version}-rh7_0-mac.yak", f"weft-{version}-rh8_0-any.yak"):
        expect(distribution in run.stdout, f"the output names {distribution}")

    n48, n7 = build / "net48", build / "net7.0"
    expected = {
        "rh7-win": {"Weft.Grasshopper.gha": n48 / "Weft.Grasshopper.gha", "Weft.Interop.dll": n48 / "Weft.Interop.dll",
                    "weft.dll": stand_ins["win-x64"]},
        "rh7-mac": {"Weft.Grasshopper.gha": n48 / "Weft.Grasshopper.gha", "Weft.Interop.dll": n48 / "Weft.Interop.dll",
                    "libweft.dylib": stand_ins["osx"]},
        "rh8": {"net48/Weft.Grasshopper.gha": n48 / "Weft.Grasshopper.gha", "net48/Weft.Interop.dll": n48 / "Weft.Interop.dll",
                "net48/weft.dll": stand_ins["win-x64"],
                "net48/runtimes/win-x64/native/weft.dll": stand_ins["win-x64"],
                "net48/runtimes/win-arm64/native/weft.dll": stand_ins["win-arm64"],
                "net7.0/Weft.Grasshopper.gha": n7 / "Weft.Grasshopper.gha", "net7.0/Weft.Interop.dll": n7 / "Weft.Interop.dll",
                "net7.0/runtimes/win-x64/native/weft.dll": stand_ins["win-x64"],
                "net7.0/runtimes/win-arm64/native/weft.dll": stand_ins["win-arm64"],
                "net7.0/libweft.dylib": stand_ins["osx"]},
    }
    for package, files in expected.items():
        folder = out / package
        for relative, source in files.items():
            target = folder / relative
            expect(target.is_file() and target.read_bytes() == source.read_bytes(), f"{package}/{relative} is {source.name}")
        present = {str(p.relative_to(folder)) for p in folder.rglob("*") if p.is_file()}
        extra = present - set(files) - {"manifest.yml", "icon.png"}
        expect(not extra, f"{package} has nothing else" + (": " + ", ".join(sorted(extra)) if extra else ""))
        check_manifest(folder, version)
    # Mono (Rhino 7 for Mac) binds DllImport("weft") only to a library beside the calling assembly.
    expect((out / "rh7-mac" / "libweft.dylib").parent == (out / "rh7-mac" / "Weft.Interop.dll").parent,
           "rh7-mac: libweft.dylib sits beside Weft.Interop.dll")

    project = ET.parse(here / "Weft.Grasshopper" / "Weft.Grasshopper.csproj").getroot()
    for framework, major in (("net48", "7"), ("net7.0", "8")):
        groups = [g for g in project.iter("ItemGroup") if g.get("Condition", "").replace(" ", "") == f"'$(TargetFramework)'=='{framework}'"]
        for package in ("RhinoCommon", "Grasshopper"):
            versions = [r.get("Version") for g in groups for r in g.iter("PackageReference") if r.get("Include") == package]
            expect(len(versions) == 1 and re.fullmatch(major + r"\.\d+\.\d+\.\d+", versions[0] or "") is not None,
                   f"{framework} references {package} {major}.x with a literal version ({versions})")
    unconditional = [r.get("Include") for g in project.iter("ItemGroup") if not g.get("Condition")
                     for r in g.iter("PackageReference")]
    expect("RhinoCommon" not in unconditional and "Grasshopper" not in unconditional,
           "no RhinoCommon or Grasshopper reference shared by both frameworks")

    workflow = here.parent / ".github" / "workflows" / "grasshopper-release.yml"
    text = workflow.read_text(encoding="utf-8") if workflow.is_file() else ""
    for token in ("windows-", "macos-", "lipo -create", "aarch64-pc-windows-msvc", "dotnet build", "Weft.Tests.csproj",
                  "package.sh", "build --platform win", "build --platform mac", "build --platform any"):
        expect(token in text, f"the release workflow has `{token}`")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
