"""`cmake --install` right after the README's first command (`./canopy run …`, which builds only
the `canopy` target) needs no file that target does not build (issue 51: it exited 1 on a missing
libcanopy_fuzz.a and left a half install).

A fresh configure of the source tree with --graphviz gives the targets `canopy` depends on; every
file the install scripts require (not OPTIONAL) must be one of theirs.

    install_after_first_command_test.py SOURCE_DIR
"""
import pathlib
import re
import subprocess
import sys
import tempfile


def closure_of_canopy(dot_file: pathlib.Path) -> set:
    labels = re.findall(r'label = "([^"\\]+)', dot_file.read_text())
    return set(labels)


def required_installed_files(build: pathlib.Path) -> list:
    required = []
    for script in build.rglob("cmake_install.cmake"):
        for line in script.read_text().splitlines():
            match = re.search(r'file\(INSTALL .*TYPE (STATIC_LIBRARY|SHARED_LIBRARY|MODULE|EXECUTABLE)'
                              r'(.*)FILES "([^"]+)"', line)
            if match and "OPTIONAL" not in match.group(2):
                required.append(pathlib.Path(match.group(3)).name)
    return required


def target_of(file_name: str) -> str:
    name = file_name.split(".")[0]
    return name[3:] if name.startswith("lib") else name


def main() -> int:
    source = pathlib.Path(sys.argv[1])
    with tempfile.TemporaryDirectory() as scratch:
        build = pathlib.Path(scratch) / "build"
        subprocess.run(["cmake", "-S", str(source), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                        f"--graphviz={build / 'deps.dot'}"],
                       check=True, stdout=subprocess.DEVNULL)
        built = closure_of_canopy(build / "deps.dot.canopy")
        required = required_installed_files(build)
        missing = [f for f in required if target_of(f) not in built]
        if not required or "canopy" not in built:
            print(f"FAIL: found no install rules ({required}) or no canopy target ({sorted(built)})")
            return 1
        if missing:
            print("FAIL: cmake --install after building only `canopy` would need files it does "
                  f"not build: {missing}")
            return 1
        print(f"ok: the {len(required)} files cmake --install requires are all built by `canopy`")
        return 0


if __name__ == "__main__":
    sys.exit(main())
