"""The ``canopy`` command of an installed package (pip install .): runs the canopy program packed
beside this file, with the package's copy of the built-in scenarios."""
import os
import sys

_HERE = os.path.dirname(os.path.abspath(__file__))


def program():
    """The packed program's path (None in a build folder's package, which packs none)."""
    path = os.path.join(_HERE, "bin", "canopy")
    return path if os.access(path, os.X_OK) else None


def main():
    path = program()
    if path is None:
        sys.stderr.write("canopy: this copy of the package has no canopy program (a build folder's "
                         "package: run build/release/app/canopy, or pip install the repository)\n")
        return 2
    env = dict(os.environ)
    scenarios = os.path.join(_HERE, "scenarios")
    if os.path.isdir(scenarios):
        env.setdefault("CANOPY_BUILTIN_SCENARIOS", scenarios)
    sys.stdout.flush()
    os.execve(path, ["canopy", *sys.argv[1:]], env)


if __name__ == "__main__":
    sys.exit(main())
