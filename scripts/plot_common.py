"""What the isolab plot scripts share: the plotting stack, imported without a display or an
install hint when missing, and HDF5 strings as text."""
import os
import sys

NEEDS = ("matplotlib, h5py and numpy (Debian: sudo apt-get install python3-matplotlib "
         "python3-h5py)")


def import_modules():
    """Imports the plotting stack, or exits 3 saying what to install."""
    try:
        import matplotlib
        matplotlib.use("Agg")  # files only: no display needed
        import h5py
        import matplotlib.pyplot as plt
        import numpy as np
    except ImportError as error:
        print(f"{os.path.basename(sys.argv[0])}: {error}; needs {NEEDS}", file=sys.stderr)
        sys.exit(3)
    return h5py, plt, np


def text(value):
    """HDF5 fixed-length strings come back as bytes."""
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    return str(value)
