"""Where the BNCS measurements are, for the doc-table scripts that read them (standard library
only). They are not in the repository: they live in ../shared/measured/bncs (docs/bncs.md says
where they come from), so scripts/check_docs.py runs these scripts with --opt-in only.
"""
import gzip
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def data_folder(given=None):
    """`given`, else $ISOLAB_BNCS_DATA, else ../shared/measured/bncs beside the repository."""
    return (given or os.environ.get("ISOLAB_BNCS_DATA")
            or os.path.join(ROOT, "..", "shared", "measured", "bncs"))


def unpack_motion(motion, folder, data=None, name=None):
    """Writes the motion into `folder` as `name` (default bncs_MOTION.csv) from the packed
    measurements; returns its path."""
    packed = os.path.join(data_folder(data), f"bncs_{motion}.csv.gz")
    if not os.path.exists(packed):
        sys.exit(f"{packed}: not there; the BNCS measurements are not in the repository "
                 f"(docs/bncs.md says where to get them)")
    csv = os.path.join(folder, name or f"bncs_{motion}.csv")
    with gzip.open(packed, "rb") as source, open(csv, "wb") as target:
        shutil.copyfileobj(source, target)
    return csv


def isolator_history(isolab, motion, folder, data=None):
    """The isolator's measured loops of `motion` as cyclic test data (`isolab shaketable
    --isolator` with models/bncs/bncs.yaml, as scripts/bncs_study.sh takes them); returns the
    file's path."""
    csv = unpack_motion(motion, folder, data)
    history = os.path.join(folder, f"{motion}_isolator.csv")
    subprocess.run([isolab, "shaketable", csv, "--model",
                    os.path.join(ROOT, "models", "bncs", "bncs.yaml"), "--isolator", history, "-q"],
                   check=True, stdout=subprocess.DEVNULL)
    return history
