"""The application service: the one door the command line and the terminal UI go through.

Each module holds one kind of request, as plain functions over typed values; progress and
cancellation are plain callables and :class:`threading.Event`, never UI objects:

- :mod:`~frp_assess.app.project`: read, check, create and save a project file;
- :mod:`~frp_assess.app.assessment`: prepare and run an assessment, show the last run again;
- :mod:`~frp_assess.app.building_run`: run a building file (several walls) and its summary
  (:mod:`~frp_assess.app.building_file`: is it one; :mod:`~frp_assess.app.building_report`:
  its report);
- :mod:`~frp_assess.app.report`: the output set, the PDF report, the export of a run;
- :mod:`~frp_assess.app.history`: a run's time history of one case under one record;
- :mod:`~frp_assess.app.study`: load, check and run a parametric study;
- :mod:`~frp_assess.app.expert`: the expert commands `simulate` and `ida` (one wall);
- :mod:`~frp_assess.app.records`: generate and check sets of records;
- :mod:`~frp_assess.app.preview`: the derived quantities the TUI previews while typing;
- :mod:`~frp_assess.app.site`: the seismic parameters of a site from its coordinates;
- :mod:`~frp_assess.app.kernel`: whether a run will first compile the numerical kernel.

The package imports its modules lazily (import ``frp_assess.app.<module>``), so that the
command line's parser does not load the numerics it does not need.
"""
