"""Application services: the layer between thin routes and the pure domain.

`container.py` builds everything once per app (store, template cache, analyzer); `gate.py`,
`verification.py` and `monitoring.py` run one use case each and keep the audit trail.
"""

from app.services.container import Services, TemplateCache, build_services

__all__ = ["Services", "TemplateCache", "build_services"]
