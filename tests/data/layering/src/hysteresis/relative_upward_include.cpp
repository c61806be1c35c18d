// A fixture of scripts/check_layering.py: an upward include by a relative path.
#include "../analysis/run_pipeline.h"
