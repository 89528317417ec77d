# JupyterLab as `make lab` starts it (loaded with --config; the user's global Jupyter
# settings in ~/.jupyter are neither used nor changed).
#
# * The course's own settings folder, .jupyter-course/lab/user-settings/ (not in git):
#   created on first start from lab/user-settings-defaults/ (no "Jupyter news?" popup,
#   no update check, a readable font size, a kernel started without asking).  What the
#   user changes in Settings is saved there and kept; delete the folder to reset.
# * The course's own layout, .jupyter-course/lab/workspaces/ (not in git): seeded from
#   lab/workspaces-defaults/ with the table of contents open in the left sidebar, so a
#   lecture's sections are one click away.  JupyterLab saves the user's layout there.
# * No dead widgets on reopening: widget views are replaced by a one-line text whenever
#   a notebook is saved (course_lib.widgets.saving.pre_save_hook).
import shutil
from pathlib import Path

HERE = Path(__file__).resolve().parent
SETTINGS = HERE / "lab" / "user-settings"
if not SETTINGS.exists():
    shutil.copytree(HERE / "lab" / "user-settings-defaults", SETTINGS)
WORKSPACES = HERE / "lab" / "workspaces"
if not WORKSPACES.exists():
    shutil.copytree(HERE / "lab" / "workspaces-defaults", WORKSPACES)

c = get_config()  # noqa: F821 (provided by Jupyter when it loads this file)
c.LabApp.user_settings_dir = str(SETTINGS)
c.LabApp.workspaces_dir = str(WORKSPACES)  # the course's own layouts
c.LabApp.news_url = None
c.LabApp.check_for_updates_class = "jupyterlab.NeverCheckForUpdate"
c.ContentsManager.pre_save_hook = "course_lib.widgets.saving.pre_save_hook"
