"""The suite's network guard (tests/network_guard.py): another machine is refused and fails the
test even when the code under test swallows the error; this machine stays reachable."""

from __future__ import annotations

import socket

import pytest

from tests.network_guard import NetworkBlockedError, is_local

pytest_plugins = ["pytester"]

# 192.0.2.0/24 is TEST-NET-1 (RFC 5737): never routed, so nothing leaves even if the guard broke.
ELSEWHERE = ("192.0.2.1", 80)


class TestIsLocal:
    @pytest.mark.parametrize("host", ["127.0.0.1", "127.1.2.3", "::1", "localhost", "0.0.0.0"])
    def test_loopback_is_local(self, host: str) -> None:
        assert is_local(socket.AF_INET, (host, 5432))

    @pytest.mark.parametrize("host", ["192.0.2.1", "10.0.0.1", "2001:db8::1", "example.com"])
    def test_anything_else_is_not(self, host: str) -> None:
        assert not is_local(socket.AF_INET, (host, 443))


class TestGuard:
    def test_a_connection_elsewhere_is_refused_and_recorded(
        self, network_attempts: list[str]
    ) -> None:
        with socket.socket() as sock, pytest.raises(NetworkBlockedError):
            sock.connect(ELSEWHERE)
        assert network_attempts == [f"connect to {ELSEWHERE!r}"]
        network_attempts.clear()  # this test meant it; let it pass

    def test_loopback_stays_reachable(self) -> None:
        with (socket.create_server(("127.0.0.1", 0)) as server,
              socket.create_connection(server.getsockname(), timeout=5) as client):
            peer, _ = server.accept()
            client.sendall(b"ok")
            assert peer.recv(2) == b"ok"
            peer.close()

    def test_a_swallowed_attempt_still_fails_the_test(self, pytester: pytest.Pytester) -> None:
        pytester.makepyfile(f"""
            import socket

            def test_swallows():
                try:
                    socket.create_connection({ELSEWHERE!r}, timeout=1)
                except OSError:
                    pass

            def test_stays_home():
                assert True
        """)
        result = pytester.runpytest("-p", "tests.network_guard", "-p", "no:cacheprovider")
        result.assert_outcomes(passed=1, failed=1)
        result.stdout.fnmatch_lines(["*tried to reach the network: connect to ('192.0.2.1', 80)*"])
