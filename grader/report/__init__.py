"""Reports: everything the grader writes from results, its markup in the jinja2 templates of ``templates/``.

    environment.py           the one jinja2 environment (HTML, text, and a terminal's, inert)
    text.py                  the report on a terminal (``grade problem-N``)
    html.py                  the HTML report with its figures, and the report inline in a notebook
    figures.py               a result's figure drawn with matplotlib, a plain plot, as base64 PNG
    data.py                  the report as plain data (``--json``)
    gradescope_results.py    Gradescope's results.json
    prairielearn_results.py  PrairieLearn's results.json
    summary.py               a batch's class summary

A new output format goes here, beside the others, reading ``grader.results``; a deployment (``grader.gradescope``,
``grader.prairielearn``, ``grader.kit``) builds a bundle and calls the format it needs.
"""
