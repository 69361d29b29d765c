"""Where the lesson site's sources are: the repository, the ``lessons/`` folder (pages,
scene files, ``conf.py``, translations, npm's ``package.json``) and its translations.

The Sphinx extension and the build command live on the application floor
(``lab/app/lesson_site/``); the lessons themselves are content, in ``lessons/``.
"""
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
"""The repository (or installed tree) that holds ``lab/``, ``renderer/``, ``compare/`` and ``lessons/``."""
LESSONS = ROOT / "lessons"
"""The lesson pages and their scene files, ``conf.py``, templates and static files."""
LOCALES = LESSONS / "locales"
"""The Japanese translations: ``ja/LC_MESSAGES/*.po`` and the search terms."""
