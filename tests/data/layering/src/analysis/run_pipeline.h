// A fixture of scripts/check_layering.py: a private header of analysis.
#pragma once
