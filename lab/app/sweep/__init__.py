"""``scanlab sweep``: comparison runs over many sources × settings, on a Dask cluster.

The modules, from the command line down to one case:

- ``sweep_command``: the options and their help (grid keys listed); ``sweep``: the whole run;
- ``sources``, ``settings`` (the grid keys' registry), ``light_sets``, ``cases``
  (grid options and files, the crossing, each case's identity);
- ``cluster`` (scheduler side: a LocalCluster or ``--scheduler``), ``case_runner`` (the
  worker plugin and task), ``isolation`` (the case process seen from the worker: time limit,
  crashes, memory), ``protocol`` (their messages), ``child`` (the case process),
  ``run_case`` (load, apply the settings, compare: the one call into the comparison),
  ``faults`` (test-only misbehaviour);
- ``table`` (Parquet, written as cases finish, resumable), ``worst`` (ranking and kept
  frames), ``panels``, ``histograms``, ``sweep_page`` (``index.html``), ``progress`` (the bar).
"""
