"""isolab from Python: time-history analysis of base-isolated structures.

    import isolab
    model = isolab.load_model("models/buildings/five_story_table9.yaml")
    model.set("excitation.ground_motion.scale", 0.4)
    result = isolab.run(model)
    result["isolator/displacement"]          # numpy array, in result.units[...]
    result.to_pandas()                      # when pandas is installed

Models are read and checked by the same reader as model files, whether loaded from a file or
built from dicts (Model.from_dict); bad input raises InputError (a ValueError) whose message
names the file, line, key and what was allowed. A run that stops early raises RunError with the
partial result attached. What the command line warns about before a run (a PGA above 3 g, a period
above 10 s, ...) is issued as an IsolabWarning, which Jupyter shows. Runs release the GIL: a
thread pool of runs uses every core.
"""

import json
import math
import numbers
import os
import warnings

from ._isolab import CyclicResult, InputError, Model, Result, RunError, __version__, load_model
from ._isolab import _compare, _cyclic, _design, _diagnose, _diagnose_building, _fit
from ._isolab import _fit_building, _parse_list, _parse_periods
from ._isolab import _replay
from ._isolab import _run, _spectrum

__all__ = ["CyclicResult", "InputError", "IsolabWarning", "Model", "Result", "RunError",
           "compare", "cyclic", "design", "diagnose", "fit", "load_model", "run", "spectrum",
           "__version__"]


class IsolabWarning(UserWarning):
    """A plausibility warning about a run's input (the command line prints it as "warning: ..."):
    values no real building or record has, such as a PGA above 3 g or an isolator beyond 1.5 m.
    The run goes on; warnings.simplefilter("error", isolab.IsolabWarning) makes them errors."""


def _number(name, value):
    """A real number (not a bool, a string or bytes) as float, else InputError naming it."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise InputError(f"{name}: {value!r} is not a number")
    return float(value)


def _finite(name, value):
    """value as a finite float, or InputError naming the argument."""
    value = _number(name, value)
    if not math.isfinite(value):
        raise InputError(f"{name}: {value} (must be a finite number)")
    return value


def _positive_finite(name, value):
    """value as a finite float > 0, or InputError naming the argument."""
    value = _number(name, value)
    if not (math.isfinite(value) and value > 0):
        raise InputError(f"{name}: {value:g} (must be a finite number > 0)")
    return value


def _as_list(value, name):
    """None, a number or a non-empty sequence of numbers, as a list of floats. A string, bytes or
    a dict is refused naming the argument: read as a sequence, "125" would be 1, 2 and 5."""
    if value is None:
        return []
    if isinstance(value, (str, bytes, dict)):
        raise InputError(f"{name}: {value!r} is not a number or a list of numbers")
    if not hasattr(value, "__len__"):
        return [_number(name, value)]
    values = [_number(f"{name}[{i}]", v) for i, v in enumerate(value)]
    if not values:
        raise InputError(f"{name}: an empty list (give a value, or leave {name} out)")
    return values


def _whole_number(name, value):
    """An integer (not a bool, a float or a string) as int, else InputError naming it."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise InputError(f"{name}: {value!r} is not a whole number")
    return int(value)


def _count(name, value, low, high):
    """A whole number in [low, high] (a seed, a number of cycles or workers), else InputError
    naming it, as the command line refuses it rather than wrapping or truncating it."""
    value = _whole_number(name, value)
    if not low <= value <= high:
        raise InputError(f"{name}: {value} (must be a whole number in [{low}, {high}])")
    return value


def _optional(check, name, value, *bounds):
    """check(name, value, *bounds) for a given value; None (left out) stays None."""
    return None if value is None else check(name, value, *bounds)


def _whole_numbers(name, value):
    """None, a whole number or a non-empty sequence of them, as a list of ints (cycles)."""
    if value is None:
        return []
    items = [value] if not hasattr(value, "__len__") or isinstance(value, (str, bytes)) else value
    if isinstance(value, dict) or not items:
        raise InputError(f"{name}: {value!r} is not a whole number or a non-empty list of them")
    return [_whole_number(name, item) for item in items]


def _model(model):
    """A Model, or the model file a path names."""
    return model if isinstance(model, Model) else load_model(_path("model", model))


def run(model, record=None, h2=None, *, angle=None, units=None, record_dt=None, scale=None,
        dt=None, free_vibration=None, fixed_base=False, trial_displacement=None, integrator=None,
        rtol=None, atol=None, samples=None, seed=None, check=True):
    """Time-history analysis: `isolab run` with its options as keyword arguments.

    model: a Model or a model file's path. record: a record file replacing the model's, or a
    numpy array of ground accelerations (then record_dt, its step in s, and units, e.g. "g" or
    "m/s^2", are required); for a building in plan, its H1 component. h2 and angle: the pair's
    second component (a file, or an array like record's) and the angle in degrees from x to H1,
    the command line's --record-h2 and --angle. scale, dt (the analysis step, model time unit), free_vibration
    ("auto" or a time in s), fixed_base, trial_displacement, integrator ("newmark" or "ida"),
    rtol and atol are the command line's --scale, --dt, --free-vibration, --fixed-base,
    --trial-displacement, --integrator, --rtol and --atol. samples and seed are --samples and
    --seed: for a model carrying a fit's uncertainty, the 5/50/95 % spread of the peaks over that
    many drawn parameter sets, in result.summary["band"] (seed, default 1, only with samples).

    Returns a Result. A run that stops early raises RunError (its .result holds the rows up to
    the failure) unless check=False. Each plausibility warning of the run (result.warnings) is
    issued as an IsolabWarning.
    """
    scale = _optional(_positive_finite, "scale", scale)
    angle = _optional(_finite, "angle", angle)
    # The run's own checks say what a step or a displacement must be; here, only that each is a
    # finite number (True is not a step of 1, nor "0.5" one of 0.5).
    dt = _optional(_finite, "dt", dt)
    record_dt = _optional(_positive_finite, "record_dt", record_dt)
    trial_displacement = _optional(_finite, "trial_displacement", trial_displacement)
    atol = _optional(_positive_finite, "atol", atol)
    if rtol is not None and not 1e-14 <= _finite("rtol", rtol) <= 0.09:
        raise InputError(f"rtol: {rtol:g} (must be in [1e-14, 0.09])")
    units = _optional(_word, "units", units)
    samples = _optional(_whole_number, "samples", samples)
    if samples is not None and not 2 <= samples <= 100000:
        raise InputError(f"samples: {samples} (draws a band: 2 or more parameter sets, at most "
                         "100000)")
    if seed is not None and samples is None:
        raise InputError("seed: seeds the parameter sets samples= draws: give samples")
    seed = 1 if seed is None else _count("seed", seed, 0, 2**32 - 1)
    samples = samples or 0
    result = _run(_model(model), record, h2, angle=angle, units=units, record_dt=record_dt,
                  scale=scale, dt=dt, free_vibration=free_vibration, fixed_base=fixed_base,
                  trial_displacement=trial_displacement, integrator=integrator, rtol=rtol,
                  atol=atol, samples=samples, seed=seed)
    for message in result.warnings:
        warnings.warn(message, IsolabWarning, stacklevel=2)
    if check and not result.ok:
        error = RunError(f"the run stopped early: {result.message}")
        error.result = result
        raise error
    return result


def cyclic(model, amplitude=None, *, period=None, cycles=None, steps_per_cycle=None,
           sequential=False, test_data=None, noise=0.0, seed=None, path=None, orbit=None,
           isolator=None, uncoupled=False, force_unit=None, length_unit=None):
    """`isolab cyclic` on one model: u(t) = u_a sin(2 pi t / T) imposed on its isolation
    assembly, or, with path or orbit, the model driven along a given path.

    amplitude and period (a number or a list), cycles and steps_per_cycle replace the model's
    cyclic section (the command line's -a, -T, -n and --steps-per-cycle; model units). sequential
    runs the tests one after another on one specimen, each from the state the last one left
    (--sequential); otherwise each starts from rest. test_data writes the loops as cyclic test
    data for fit and diagnose (--test-data), with Gaussian force noise relative to each test's RMS
    force (--noise) from seed (--seed, default 1). Arguments of the other mode (path and orbit,
    or the sinusoidal test) raise InputError naming them.

    Returns a CyclicResult (the loop: time, displacement, force, component_force; per cycle the
    dissipated energy, peak force and each component's slider at +u_a), or a list of them, periods
    outer and amplitudes inner, when amplitude or period is a list.

    path (a CSV file or a list: time and displacement, or displacement_x and displacement_y, with
    the measured force when there is one; --path) or orbit ("circle" or "figure8" of radius
    amplitude, period, cycles, steps_per_cycle; --orbit) drives the model along it instead: a
    measured test predicted blind, or a biaxial path through the laws' coupled forms (uncoupled:
    each law along x and y; --uncoupled). model may then also be a plan model file's path, whose
    isolators are driven (isolator: only that one; --isolator). force_unit and length_unit are
    the units of path files without a "# units:" line. Returns a list of dicts, one per model
    (isolator) and path, as `isolab cyclic --path --json` has them, with the histories as numpy
    arrays: "time", "displacement", "force" (n or n x 2), "component_force" (one array per
    component), "measured" and "comparison" (e2, nrmse: RMS error over the measured force's RMS,
    error_over_range: over its peak-to-peak range, peak_measured, peak_modelled) when the
    path has a force, "dissipated", "peak_force", "peak_displacement", "cycles" (an orbit's).
    """
    cycles = _optional(_count, "cycles", cycles, 1, 2**31 - 1)
    steps_per_cycle = _optional(_count, "steps_per_cycle", steps_per_cycle, 1, 2**31 - 1)
    noise = _finite("noise", noise)
    seed = _optional(_count, "seed", seed, 0, 2**32 - 1)
    given = {"sequential": sequential, "test_data": test_data is not None, "noise": noise != 0.0,
             "seed": seed is not None, "isolator": isolator is not None, "uncoupled": uncoupled,
             "force_unit": force_unit is not None, "length_unit": length_unit is not None,
             "amplitude": amplitude is not None, "period": period is not None,
             "cycles": cycles is not None, "steps_per_cycle": steps_per_cycle is not None}
    if path is not None or orbit is not None:
        other = ["sequential", "test_data", "noise", "seed"]
        if path is not None:  # the path gives its own history
            other += ["amplitude", "period", "cycles", "steps_per_cycle"]
    else:
        other = ["isolator", "uncoupled", "force_unit", "length_unit"]
        if test_data is None:
            other += ["noise", "seed"]
    for name in other:
        if given[name]:
            raise InputError(f"{name}: does not apply to this cyclic test "
                             "(path and orbit, or the sinusoidal test with its test data)")
    if path is not None or orbit is not None:
        target = model if isinstance(model, Model) else _path("model", model)
        paths = [] if path is None else _paths("path", path)
        return _replay(target, paths, _word("orbit", orbit), _as_list(amplitude, "amplitude"),
                       _as_list(period, "period"), cycles, steps_per_cycle,
                       _word("isolator", isolator), uncoupled, _word("force_unit", force_unit),
                       _word("length_unit", length_unit))
    runs = _cyclic(_model(model), _as_list(amplitude, "amplitude"), _as_list(period, "period"),
                   cycles, steps_per_cycle,
                   sequential, _optional_path("test_data", test_data), noise,
                   1 if seed is None else seed)
    several = hasattr(amplitude, "__len__") or hasattr(period, "__len__")
    return runs if several else runs[0]


def _spectrum_list(value, name, parse=_parse_list):
    """A number, a sequence of numbers, or the command line's text ("0.05:5:0.05", "0.02,0.05")."""
    if isinstance(value, str):
        return parse(value, name)
    return _as_list(value, name)


def _default_periods():
    """The command line's default --periods 0.05:5:0.05, the same 100 numbers."""
    return [float(f"{0.05 + k * 0.05:.12g}") for k in range(100)]


def spectrum(record, h2=None, *, periods=None, damping=0.05, ductility=None, alpha=0.0,
             points_per_period=100, scale=1.0, units=None, record_dt=None, length_unit="m",
             max_steps=1e9):
    """`isolab spectrum`: elastic (and, given ductility, constant-ductility) response spectra.

    record: a record file, or a numpy array of accelerations (then record_dt in s and units are
    required). periods (s; default the command line's 0.05 to 5 by 0.05), damping and ductility
    (a number, a list, or the command line's text: periods="0.05:5:0.05" or "0.5,1,2",
    damping="0.02,0.05"), alpha, points_per_period, scale, units, record_dt and length_unit are the
    command line's --periods, --damping, --ductility, --alpha, --points-per-period, --scale,
    --units, --dt and --length-unit; max_steps is --max-steps (a spectrum counted above it is
    refused before it starts).

    Returns a dict named as the HDF5 spectrum file: "period", "damping", "elastic" {"D", "V",
    "A", "A_g", "time_of_peak"} (damping x period arrays) and, with ductility,
    "constant_ductility" {"ductility", "strength_ratio", "D_y", "V_y", "A_y", "A_y_g", "u_m",
    "achieved_ductility" (damping x ductility x period), ...}; "record" and "units", which gives
    each array's unit as the command line's table does: D in length_unit, V in length_unit/s, A
    in length_unit/s^2 (m/s^2 by default), A_g in g (units["g"] is g in length_unit/s^2).

    h2: the pair's second component (a file or an array, read as record is), as `isolab spectrum
    H1 H2`: then "h1", "h2", "geometric_mean", "rotd50" and "rotd100" (each as "elastic"; rotd100
    also "angle", degrees from H1 towards H2) replace "elastic", with "record_h2"; ductility is
    refused for a pair.
    """
    if damping is None:
        raise InputError("damping: None (give a ratio, e.g. 0.05, or a list of them)")
    return _spectrum(record, h2, _spectrum_list(periods, "periods", _parse_periods) or
                     _default_periods(), _spectrum_list(damping, "damping"),
                     _spectrum_list(ductility, "ductility"), _finite("alpha", alpha),
                     _count("points_per_period", points_per_period, 1, 2**31 - 1),
                     _positive_finite("scale", scale), _optional(_word, "units", units),
                     _optional(_positive_finite, "record_dt", record_dt),
                     _word("length_unit", length_unit), _number("max_steps", max_steps))


def _one_of(first, first_name, building, what):
    """Exactly one of the cyclic specification and building=, as the command line's options
    exclude each other; what says what each reads."""
    if first is not None and building is not None:
        raise InputError(f"building= excludes {first_name}=")
    if first is None and building is None:
        raise InputError(f"give {first_name}= (cyclic tests) or building= ({what})")


def _refuse(given, why):
    """InputError naming the first keyword given that does not apply."""
    for name, value in given:
        if value:
            raise InputError(f"{name}= {why}")


def fit(data, model=None, *, building=None, offsets=None, output=None, seed=1, budget=60000,
        global_budget=None, cross_validate=False, model_form=False, cycles=None, specimen=None,
        force_unit=None,
        length_unit=None, threads=0, force=False, quiet=False):
    """`isolab fit`: identifies an assembly's parameters from measured cyclic tests (CMA-ES), or
    with building, a whole building model from its shake-table motions by output error.

    data: a cyclic-test CSV file or a list of them; model: the specification (component types
    and counts, YAML). seed, budget, cycles (1-based, a number or a list), specimen
    ("sequential" or "independent"), force_unit and length_unit (both needed for a file without
    a "# units:" line), threads (speed only: the result is the same), force (beyond the work
    limit) and quiet are the command line's --seed, --budget, --cycles, --specimen,
    --force-unit, --length-unit, --threads, --force and -q; progress goes to stderr unless quiet.

    Returns the dict `isolab fit --json` prints (but its "output"): "e2" (the paper's sum over
    tests), "e2_mean", "e2_per_test", "components" (name, type and the mathematical parameters),
    "units", "energy_per_cycle", "identified_range", "evaluations", "restarts", "seconds",
    "stop" ("converged" or "budget") and "stop_reason", "identifiability" (findings, empty when
    none), "testing_factors", "notes" (the components the fit gave no stiffness, which a model
    would leave out), "work", "seed", "one_specimen". The cyclic fit writes no file.

    building: a building fit specification (YAML, docs/building_fit.md) instead of model, as
    `isolab fit --building`: data are shake-table CSV files, one per motion, or with `input:
    force` in the spec force-driven tests in the cyclic-test format (then force_unit and
    length_unit as above). offsets ("pre-event", the default, or "none": the accelerometers'
    offsets), specimen, seed, budget, global_budget (the CMA-ES stage's simulations before the
    least-squares refinement; 0: refine from the start alone), threads and quiet are the command
    line's options; output is
    its -o, the fitted model file (YAML; default <spec stem>.fitted.yaml in the working
    directory), written as the command line writes it. Returns the dict `isolab fit --building
    --json` prints: "parameters" (name, start, value, sigma, log, interval_95, at_bound),
    "channels" (motion, channel, nrmse_start, nrmse), "not_separated", "identified_range",
    "objective_start", "objective", "samples", "effective_samples", "correlation_time",
    "evaluations", "global_evaluations", "iterations", "stop" ("converged", "stalled" or
    "budget"), "decrement", "step", "stop_reason", "seconds", "sequential" and "output". cycles
    and force are refused with building, offsets, output, global_budget and cross_validate
    without it.

    cross_validate=True (building, two motions or more, not one specimen) is `isolab fit
    --building --cross-validate --json`: each motion held out in turn, the building fitted to the
    others and its prediction of the held-out motion compared with it; returns {"folds": [...],
    "seconds"} (docs/building_fit.md) and writes no model (output is refused with it).

    model_form=True (building, two motions or more, not one specimen) is `isolab fit --building
    --model-form --json`: the fit to every motion, then each motion held out in turn; the model is
    written with those fits as its uncertainty's model_form, which prediction bands (run and
    shaketable samples) draw beside the fit's covariance; the result adds "model_form" ("fits",
    "parameters" with sigma_fit and sigma_drawn).
    """
    _one_of(model, "model", building, "shake-table motions")
    data = _paths("data", data)
    if building is not None:
        _refuse([("cycles", cycles is not None), ("force", force)],
                "applies to cyclic tests, not to building=")
        if cross_validate and model_form:
            raise InputError("cross_validate=True and model_form=True: the model form already "
                             "fits each motion held out; give one of the two")
        if cross_validate and output is not None:
            raise InputError("output= with cross_validate=True: the cross-validation writes no "
                             "model (fit all the motions without it for the model)")
        return json.loads(_fit_building(data, _path("building", building),
                                        _optional_path("output", output), seed, budget,
                                        -1 if global_budget is None else global_budget,
                                        _specimen(specimen), _word("offsets", offsets),
                                        _word("force_unit", force_unit),
                                        _word("length_unit", length_unit), threads,
                                        bool(cross_validate),
                                        bool(model_form), quiet))
    _refuse([("offsets", offsets is not None), ("global_budget", global_budget is not None),
             ("cross_validate", cross_validate), ("model_form", model_form)],
            "applies to building=, not to cyclic tests")
    _refuse([("output", output is not None)],
            "applies to building=: the cyclic fit writes no file (its components are in the "
            "result)")
    cycles = _whole_numbers("cycles", cycles)
    return _fit(data, _path("model", model), seed, budget, cycles, _specimen(specimen),
                _word("force_unit", force_unit), _word("length_unit", length_unit), threads,
                force, quiet)


def diagnose(data, base=None, *, building=None, offsets=None, seed=1, budget=12000,
             specimen=None, force_unit=None, length_unit=None, threads=0, force=False,
             quiet=False):
    """`isolab diagnose`: which physical effect a base model misses, from cyclic tests, or with
    building, from a building's shake-table motions.

    data: a cyclic-test CSV file or a list of them; base: the base specification (YAML). seed,
    budget (per fit), specimen, force_unit, length_unit, threads, force and quiet are the command
    line's options; progress goes to stderr unless quiet.

    Returns the report the command line writes as OUT.json, as a dict: "head" (its first lines:
    the verdict on the residual and what the effects do and do not explain), "effects" (the
    effects added, or ["none"]), "steps" (each with its evidence, the candidates weighed, e^2
    and BIC before and after, the component added), "base" and "final" (e2, e2_mean,
    e2_per_test, bic, components), "verdict" (kind "noise", "structured" or "unexplained",
    headline, where, tables), "identifiability", "noise_floor_e2", "stop", "stop_reason",
    "last_candidates", "loops", "samples". The files (.md, .model.yaml, residual CSV and plot)
    stay with the command line.

    building: a building fit specification (as fit's building=) instead of base, as `isolab
    diagnose --building`: data are shake-table CSV files, one per motion; offsets ("pre-event" or
    "none"), specimen, seed, budget, threads and quiet are the command line's options. The
    building is fitted by output error, the isolator's loops reconstructed with the fitted masses
    and diagnosed, and an effect named only where the building's own refit bears it out. Returns
    the same report, its head opening with the building's lines, with "building": "base" (and
    "refit" when an effect was tried: objective_start, objective, effective_samples, parameters,
    channels), "added", "confirmed", "bic_base", "bic_refit", "effective_samples",
    "conclusion". Its files, the final building model among them, stay with the command line.
    force_unit, length_unit and force are refused with building, offsets without it.
    """
    _one_of(base, "base", building, "a building's shake-table motions")
    data = _paths("data", data)
    if building is not None:
        if force_unit is not None or length_unit is not None:
            raise InputError("force_unit= and length_unit= apply to cyclic tests, not to building= "
                             "(shake-table motions carry their units in the column names)")
        _refuse([("force", force)], "applies to cyclic tests, not to building=")
        return json.loads(_diagnose_building(data, _path("building", building), seed, budget,
                                             _specimen(specimen),
                                             _word("offsets", offsets), threads, quiet))
    _refuse([("offsets", offsets is not None)], "applies to building=, not to cyclic tests")
    return json.loads(_diagnose(data, _path("base", base), seed, budget,
                                _specimen(specimen), _word("force_unit", force_unit),
                                _word("length_unit", length_unit), threads, force, quiet))


def compare(study, *, output=None, jobs=0, quiet=False, free_vibration=None, runs=None):
    """`isolab compare`: a study's isolator variants under its records and scale factors.

    study: the study file (YAML). output (the folder; default the study's output.directory, else
    its file name's stem), jobs (worker processes; 0: every hardware thread), quiet and
    free_vibration ("auto" or a time in s) and runs ("none", "summary" or "full": the per-run
    files; default the study's output.runs, else "full") are the command line's -o, -j, -q,
    --free-vibration and --runs; progress goes to stderr unless quiet. Runs on local worker
    processes, the GIL released (MPI stays with the command line under mpirun).

    Writes what the command line writes: runs/<variant>/<record>_x<scale>.h5 (unless runs is
    "none") and summary.csv and
    summary.h5 in the output folder. Returns a dict: "runs" (one row per run in job order:
    variant, record, scale, completed, message, file, record_units, pga and each quantity with
    its "ratio <quantity>" to the reference variant) and "statistics" (one row per variant and
    scale: completed and "mean <q>", "max <q>", "mean_ratio <q>", "max_ratio <q>"), both columns
    of equal length for pandas.DataFrame; "units" per quantity, "reference", "failed" (runs that
    failed; their quantities are NaN) and "output" (the folder). A plan study's quantities are
    its four (resultant isolator displacement and base shear, floor rotation, torsional
    amplification), a one-direction study's its five; "units" lists them.
    """
    return _compare(_path("study", study), _optional_path("output", output),
                    _count("jobs", jobs, 0, 2**31 - 1), quiet,
                    None if free_vibration is None else str(free_vibration),
                    None if runs is None else str(runs))


def design(design_file, *, output=None, jobs=0, quiet=False):
    """`isolab design`: an isolated building designed as ASCE 7-16 chapter 17 or EN 1998-1 section
    10 asks (the target's code).

    design_file: the design file (YAML, docs/design.md). output (the folder; default the design's
    output.directory, else its file name's stem), jobs (worker processes; 0: every hardware
    thread) and quiet are the command line's -o, -j and -q. Runs on local worker processes, the GIL
    released.

    Writes what the command line writes (the bound models, the synthetic records, each run's
    summary file, the histories kept for figures, design.md and the CSV files) except the
    figures: scripts/plot_design.py OUTPUT draws them. Returns a dict: "bounds" (per bound:
    "model", the written YAML; "elf", its D_M, T_M (s), beta_M, B_M, k_M, V_b and D_TM;
    "values", the response-history design values D_M, D_TM, V_b, isolator_force,
    story_drift_ratio (%), floor_acceleration (g), residual_displacement), "governing" (the bound
    of the largest value per quantity), "records" (name, files, factor), "period_range" (s),
    "statistic" ("mean" with at least 7 records, else "max"), "summary" (the command line's text)
    "output", "warnings" (each run warning, per bound: "bound", "text" and "runs", the count of
    the bound's runs that gave it; each also issued as an IsolabWarning), "code" ("ASCE 7-16" or
    "EN 1998-1:2004", the target's), "design_values" ("D_TM" and "V_b" by the code's rule, and
    "V_s" with r_i on an ASCE 7-16 design: "value",
    the governing "bound", its "response_history" value, the "factor" (gamma_x) and "floor" on
    the "elf" value, and the "rule") and "checks" (each check of design.md: "check", "clause",
    "unit", "demand", "limit" (None where none is known), "basis", "verdict" ("met", "EXCEEDED"
    or "not checked") and "isolators") and "parts" (each story's drift ratio and shear, each
    floor's acceleration, each bearing's displacement and greatest and least axial load:
    "quantity", "part", "unit", "values" per bound (None where a part has no value, a story
    without a height its drift ratio) and the "governing" bound).
    Lengths and forces in the model's units. Raises RuntimeError when a run fails.

    The folder must be new, empty, or an earlier design's (design_manifest.txt lists what it
    wrote); an earlier design is kept untouched until this one completes.
    """
    result = _design(_path("design_file", design_file), _optional_path("output", output),
                     _count("jobs", jobs, 0, 2**31 - 1),
                     quiet)
    for warning in result["warnings"]:
        warnings.warn(f"{warning['bound']}: {warning['text']} (in {warning['runs']} runs)",
                      IsolabWarning, stacklevel=2)
    return result


def _path(name, value):
    """A file or folder argument as str: a str, bytes or os.PathLike. Anything else (a number,
    a dict, an array) is refused naming the argument, never turned into a file name; so is an
    empty path, which would otherwise read as the argument left out."""
    if isinstance(value, (str, bytes, os.PathLike)):
        path = os.fsdecode(os.fspath(value))
        if not path:
            raise InputError(f"{name}: an empty path (give one, or leave {name} out)")
        return path
    raise TypeError(f"{name}: expected a path (str or os.PathLike), not {type(value).__name__}")


def _specimen(value):
    """specimen=: "sequential", "independent", or "" (the data's header) when left out."""
    if value is not None and value not in ("sequential", "independent"):
        raise InputError(f"specimen: {value!r} (expected sequential or independent)")
    return value or ""


def _word(name, value):
    """A text argument (a unit, a mode) as str, "" when left out (None); an empty one is refused,
    as the command line refuses an empty value, not read as the default."""
    if value is None:
        return ""
    if not isinstance(value, str) or not value:
        raise InputError(f"{name}: {value!r} (give a word, or leave {name} out)")
    return value


def _optional_path(name, value):
    """_path, or "" (the default) for None."""
    return "" if value is None else _path(name, value)


def _paths(name, data):
    """One path or a list of them, as a list of str (a dict is refused: read as a list, its keys
    would be taken for the paths and its values dropped)."""
    if isinstance(data, (str, bytes, os.PathLike)):
        return [_path(name, data)]
    if isinstance(data, dict):
        raise TypeError(f"{name}: expected a path or a list of paths, not dict")
    try:
        items = list(data)
    except TypeError:
        raise TypeError(f"{name}: expected a path or a list of paths, not "
                        f"{type(data).__name__}") from None
    return [_path(f"{name}[{i}]", d) for i, d in enumerate(items)]


def _to_pandas(result):
    """The time histories as a pandas DataFrame indexed by time.

    Columns are "<series>" or "<series>/<column>" as in the CSV results ("displacement/base",
    "isolator/force"); their units are in df.attrs["units"]. Needs pandas.
    """
    try:
        import pandas
    except ImportError as error:
        raise ImportError("Result.to_pandas() needs pandas (Debian: python3-pandas)") from error
    columns, units = {}, {}
    for name in result.names:
        if name == "time":
            continue
        values = result[name]
        if values.ndim == 1:
            columns[name] = values
            units[name] = result.units[name]
        else:
            for i, column in enumerate(result.columns[name]):
                columns[f"{name}/{column}"] = values[:, i]
                units[f"{name}/{column}"] = result.units[name]
    frame = pandas.DataFrame(columns, index=pandas.Index(result["time"], name="time"))
    frame.attrs["units"] = units
    return frame


Result.to_pandas = _to_pandas
Model.run = run
