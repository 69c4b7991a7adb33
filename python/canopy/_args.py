"""Arguments of the public functions, checked with the command line's rules before any work:
each refusal is a canopy.ScenarioError (a ValueError) naming the function and the argument, as
the CLI names the option ("canopy.run: size: expected …, got …")."""
import math
import numbers
import os
import stat

from . import _canopy

# The command line's ranges (app/cli.cpp, app/cmd_run.cpp, app/cmd_sweep.cpp).
MAX_JOBS = 1024
MAX_FRAME_EVERY = 1_000_000
MAX_SEED = 2**64 - 1
MIN_IMAGE_SIDE, MAX_IMAGE_SIDE = _canopy._image_sides()
MAX_COORDINATE = 1e7  # m: Box2D keeps positions as floats


def error(function, field, reason):
    """A ScenarioError with the attributes the loader's carry (file: the function)."""
    text = f"{function}: {field}: {reason}" if field else f"{function}: {reason}"
    exception = _canopy.ScenarioError(text)
    exception.file, exception.field, exception.reason = function, field, reason
    return exception


def _shown(value):
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def number(value, function, field, low=-math.inf, high=math.inf, low_open=False,
           expected="a finite number"):
    """A real number (not a bool, not NaN or infinite) in [low, high] ((low, high] with
    low_open) → float."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise error(function, field, f"expected {expected}, got {_shown(value)}")
    x = float(value)
    if not math.isfinite(x) or x < low or x > high or (low_open and x == low):
        raise error(function, field, f"expected {expected}, got {_shown(value)}")
    return x


def integer(value, function, field, low, high):
    """An integer (not a bool; a float only when whole) in [low, high] → int."""
    expected = f"an integer in [{low}, {high}]"
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise error(function, field, f"expected {expected}, got {_shown(value)}")
    if isinstance(value, numbers.Integral):
        n = int(value)
    else:
        x = float(value)
        if not math.isfinite(x) or x != math.floor(x):
            raise error(function, field, f"expected {expected}, got {_shown(value)}")
        n = int(x)
    if not low <= n <= high:
        raise error(function, field, f"expected {expected}, got {_shown(value)}")
    return n


def boolean(value, function, field):
    if not isinstance(value, (bool, numbers.Integral)) or value not in (0, 1):
        raise error(function, field, f"expected True or False, got {_shown(value)}")
    return bool(value)


def seed(value, function, field="seed"):
    """None or an integer in [0, 2⁶⁴ − 1] (the CLI's --seed)."""
    return None if value is None else integer(value, function, field, 0, MAX_SEED)


def sequence(value, function, field, length, item, expected):
    """A list, tuple or 1-D array of exactly `length` items, each through item(x, subfield)."""
    if isinstance(value, (str, bytes, dict)) or not hasattr(value, "__len__") \
            or not hasattr(value, "__iter__"):
        raise error(function, field, f"expected {expected}, got {_shown(value)}")
    items = list(value)
    if len(items) != length:
        raise error(function, field, f"expected {expected}, got {len(items)} values")
    return [item(x, f"{field}[{i}]") for i, x in enumerate(items)]


def coordinates(value, function, field, length):
    """`length` finite coordinates within ±1e7 m."""
    return sequence(value, function, field, length,
                    lambda x, f: number(x, function, f, -MAX_COORDINATE, MAX_COORDINATE,
                                        expected="a finite coordinate within ±1e7 m"),
                    f"{length} finite coordinates (m)")


def region(value, function, field="aoi"):
    """(x_min, y_min, x_max, y_max) with x_max > x_min and y_max > y_min."""
    box = coordinates(value, function, field, 4)
    if not (box[2] > box[0] and box[3] > box[1]):
        raise error(function, field, "expected (x_min, y_min, x_max, y_max) with x_max > x_min "
                                     f"and y_max > y_min, got {_shown(value)}")
    return box


def path(value, function, field):
    """A str or os.PathLike (not empty, no NUL) → str."""
    if not isinstance(value, (str, os.PathLike)):
        raise error(function, field, f"expected a path (str or os.PathLike), got {_shown(value)}")
    text = os.fspath(value)
    if isinstance(text, bytes):
        raise error(function, field, "expected a str path, got bytes")
    if not text or "\0" in text:
        raise error(function, field, f"expected a non-empty path without NUL, got {_shown(value)}")
    return text


def _not_ours(text):
    """What `text` is when it exists and is neither a regular file nor a link, else None."""
    try:
        mode = os.lstat(text).st_mode
    except OSError:
        return None
    if stat.S_ISREG(mode) or stat.S_ISLNK(mode):
        return None
    return ("a directory" if stat.S_ISDIR(mode) else "a FIFO" if stat.S_ISFIFO(mode)
            else "a socket" if stat.S_ISSOCK(mode) else "a device" if
            stat.S_ISCHR(mode) or stat.S_ISBLK(mode) else "not a regular file")


def output_file(value, function, field):
    """A path canopy may write a file at: absent, a regular file or a link (replaced, never
    followed); a device, FIFO, socket or directory is refused as the CLI refuses it (exit 2)."""
    text = path(value, function, field)
    what = _not_ours(text)
    if what is not None:
        raise error(function, field, f"{_shown(text)} exists and is {what}; canopy replaces "
                                     "only regular files (choose another path)")
    return text


def output_dir(value, function, field):
    """A folder canopy may write into: new or an existing directory (a link the user named is
    followed), as the CLI's --out DIR."""
    text = path(value, function, field)
    if os.path.exists(text) and not os.path.isdir(text):
        raise error(function, field, f"expected a directory (new or existing), got "
                                     f"{_shown(text)}, which exists and is not a directory")
    return text


def paths(value, function, field):
    """A list or tuple of paths (--allow-path DIR, repeatable)."""
    if isinstance(value, (str, bytes, os.PathLike)) or not isinstance(value, (list, tuple)):
        raise error(function, field, f"expected a list of folders, got {_shown(value)}")
    return [path(p, function, f"{field}[{i}]") for i, p in enumerate(value)]


def image_size(value, function, field="size"):
    """(width, height) px, each in the CLI's --size range."""
    return sequence(value, function, field, 2,
                    lambda x, f: integer(x, function, f, MIN_IMAGE_SIDE, MAX_IMAGE_SIDE),
                    f"(width, height) integers in [{MIN_IMAGE_SIDE}, {MAX_IMAGE_SIDE}] px")
