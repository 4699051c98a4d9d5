"""Application services: the layer between thin routes and the pure domain.

`container.py` builds every service once per app (store, template cache, analyzer, and one
service per use case); `gate.py`, `verification.py`, `extensions.py`, `curation.py` and
`monitoring.py` run one use case each and keep the audit trail; `audit_trail.py`,
`template_catalog.py` and `access.py` read what routes show.
"""

from app.services.container import Components, Deciders, build_components, build_deciders
from app.services.template_cache import TemplateCache

__all__ = ["Components", "Deciders", "TemplateCache", "build_components", "build_deciders"]
