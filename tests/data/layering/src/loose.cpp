// A fixture of scripts/check_layering.py: a source of no area.
