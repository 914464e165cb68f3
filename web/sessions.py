"""Browser sessions, each isolated in its own temporary folder.

A session is known by a random id that the server makes (:func:`secrets.token_urlsafe`)
and sends as a cookie; an id the server did not make, or has forgotten, is never looked
up on disk: the browser simply gets a new session.  Each session's files live in a folder
the server names under one temporary root; no name from the user ever reaches a path.
A session idle for longer than ``idle_seconds`` is removed with its folder (:meth:`sweep`,
run by the app every minute), and the whole root at shutdown (:meth:`close`).
"""
from __future__ import annotations

import secrets
import shutil
import tempfile
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["Session", "SessionStore", "COOKIE"]

#: The cookie that carries the session id.
COOKIE = "crankdyn_session"


@dataclass
class Session:
    """One browser session: its folder and what its pages hold between requests."""

    id: str
    folder: Path
    last_used: float
    #: per-page state (``"engine"``, ``"linkage"``: :class:`web.pages.PageState`)
    pages: dict = field(default_factory=dict)
    lock: threading.Lock = field(default_factory=threading.Lock)


class SessionStore:
    """Every live session, by id, with its folder under ``root`` (a new temporary folder
    when None).  At most ``max_sessions`` live at once: a new one beyond that removes the
    one idle the longest."""

    def __init__(self, root=None, idle_seconds: float = 3600.0, max_sessions: int = 500):
        self.root = Path(root) if root is not None else Path(
            tempfile.mkdtemp(prefix="crankdyn-web-"))
        self.root.mkdir(parents=True, exist_ok=True)
        self.idle_seconds = float(idle_seconds)
        self.max_sessions = int(max_sessions)
        self._sessions: dict[str, Session] = {}
        self._lock = threading.Lock()

    def __len__(self):
        return len(self._sessions)

    def get(self, sid) -> Session | None:
        """The live session of id ``sid`` (touched), or None."""
        with self._lock:
            s = self._sessions.get(sid) if isinstance(sid, str) else None
            if s is not None:
                s.last_used = time.monotonic()
            return s

    def new(self) -> Session:
        """A new session with its own empty folder."""
        with self._lock:
            while len(self._sessions) >= self.max_sessions:
                oldest = min(self._sessions.values(), key=lambda s: s.last_used)
                self._drop(oldest.id)
            sid = secrets.token_urlsafe(24)
            folder = self.root / f"s{len(sid)}-{secrets.token_hex(8)}"
            folder.mkdir()
            s = Session(sid, folder, time.monotonic())
            self._sessions[sid] = s
            return s

    def _drop(self, sid):
        s = self._sessions.pop(sid, None)
        if s is not None:
            shutil.rmtree(s.folder, ignore_errors=True)

    def sweep(self, now: float | None = None) -> int:
        """Remove every session idle for longer than ``idle_seconds``; how many."""
        now = time.monotonic() if now is None else now
        with self._lock:
            old = [sid for sid, s in self._sessions.items()
                   if now - s.last_used > self.idle_seconds]
            for sid in old:
                self._drop(sid)
        return len(old)

    def close(self) -> None:
        """Forget every session and remove the root folder."""
        with self._lock:
            self._sessions.clear()
        shutil.rmtree(self.root, ignore_errors=True)
