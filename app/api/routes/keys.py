"""API keys over HTTP, for admins (the first admin key comes from `safegate keys create`).

The secret of a new key is in the creation answer only; the store keeps its SHA-256.
`GET /keys/me` tells any key holder who they are (the curator page uses it). Revoking a key
closes its open websockets (`app/api/revocations.py`).
"""

from __future__ import annotations

from fastapi import APIRouter, Request, status
from pydantic import BaseModel, ConfigDict, Field
from starlette.concurrency import run_in_threadpool

from app.api.deps import AdminKey, AnyKey, KeysDep
from app.api.openapi import problem_responses
from app.api.read_schemas import CreatedKeyResponse, KeyListResponse, KeyResponse
from app.api.revocations import open_websockets
from app.store.records import ApiKeyRecord, ApiKeyRole

router = APIRouter(tags=["keys"])


class CreateKeyRequest(BaseModel):
    """A key to issue: its role and a name to recognise it by."""

    model_config = ConfigDict(json_schema_extra={"examples": [
        {"role": "robot", "name": "kitchen robot planner"}]})

    role: ApiKeyRole = Field(description="robot (gate, verify, monitor), curator (template "
                                         "writes), admin (keys, and everything)")
    name: str = Field(min_length=1, max_length=200)


def _key(record: ApiKeyRecord) -> KeyResponse:
    return KeyResponse.model_validate(record.model_dump(exclude={"key_hash"}))


@router.get("/keys/me", response_model=KeyResponse, summary="Who am I: the presented key",
            responses=problem_responses(503))
def whoami(key: AnyKey) -> KeyResponse:
    """The key the caller presented: id, role, name."""
    return _key(key)


@router.get("/keys", response_model=KeyListResponse, summary="List API keys",
            responses=problem_responses(403, 503))
def list_keys(keys: KeysDep, _: AdminKey) -> KeyListResponse:
    """Every key, revoked ones included (never their secrets)."""
    return KeyListResponse(keys=[_key(k) for k in keys.list()])


@router.post("/keys", response_model=CreatedKeyResponse, status_code=status.HTTP_201_CREATED,
             summary="Issue an API key", responses=problem_responses(403, 503))
def create_key(body: CreateKeyRequest, keys: KeysDep, _: AdminKey) -> CreatedKeyResponse:
    """Issue a key; the answer holds its secret, shown this once."""
    record, secret = keys.issue(body.role, body.name)
    return CreatedKeyResponse(**dict(_key(record)), key=secret)


@router.delete("/keys/{key_id}", response_model=KeyResponse, summary="Revoke an API key",
               responses=problem_responses(403, 404, 503))
async def revoke_key(key_id: str, request: Request, keys: KeysDep,
                     _: AdminKey) -> KeyResponse:
    """Revoke a key for good; its open websockets are closed (code 4401) before this answers."""
    record = await run_in_threadpool(keys.revoke, key_id)
    await open_websockets(request.app).close_key(key_id)
    return _key(record)
