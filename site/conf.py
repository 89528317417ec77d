"""Sphinx configuration of the course website (built by ``tools/build_site.py``).

The notebooks arrive here already executed (``nb_execution_mode = "off"``); MathJax 2.7 is
served from ``_static/mathjax`` (copied from the ``jupyter-server-mathjax`` package), so
the site loads nothing from the network.
"""

from __future__ import annotations

project = "Geometric continuity of parametric curves"
author = "the course authors"
copyright = "the course authors"
extensions = ["myst_nb"]
exclude_patterns = ["_build", "**.ipynb_checkpoints"]
source_suffix = {".md": "myst-nb", ".ipynb": "myst-nb"}

# ---- notebooks: executed by tools/build_site.py (cached), never here
nb_execution_mode = "off"
nb_merge_streams = True
nb_output_stderr = "remove-warn"
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence"]
myst_heading_anchors = 3
myst_dmath_double_inline = True
myst_update_mathjax = False  # its MathJax 3 settings; MathJax 2 is configured below  # $$...$$ inside a paragraph, as JupyterLab renders it
suppress_warnings = ["mystnb.unknown_mime_type", "myst.header"]

# ---- math: MathJax 2.7, local (relative to _static/)
mathjax_path = "mathjax/MathJax.js?config=TeX-AMS-MML_HTMLorMML-full"
mathjax2_config = {
    # MyST and MyST-NB write all math (prose and sympy's LaTeX outputs) as \(..\) / \[..\];
    # a stray "$" is left alone (and caught by tests/test_site.py).
    "tex2jax": {"inlineMath": [["\\(", "\\)"]], "displayMath": [["\\[", "\\]"]]},
    "HTML-CSS": {
        "availableFonts": ["STIX-Web"],
        "preferredFont": "STIX-Web",
        "webFont": "STIX-Web",
        "imageFont": None,
        "linebreaks": {"automatic": True},
    },
    "showMathMenu": False,
    "messageStyle": "none",
}

# ---- theme: sphinx-book-theme (pydata-sphinx-theme; its fonts and icons are bundled)
html_theme = "sphinx_book_theme"
html_title = "Geometric continuity"
html_static_path = ["_static"]
html_css_files = ["course.css"]
html_last_updated_fmt = None
html_copy_source = False
html_show_sourcelink = False
html_theme_options = {
    "show_toc_level": 2,
    "show_navbar_depth": 1,
    "use_download_button": False,
    "use_fullscreen_button": False,
    "use_repository_button": False,
    "home_page_in_toc": True,
    "navigation_with_keys": False,
    "pygments_light_style": "default",
}


def setup(app):
    # MathJax on every page: the navigation shows lecture titles with math on all of them
    app.set_html_assets_policy("always")
