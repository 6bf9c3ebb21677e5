# SPDX-License-Identifier: BSD-2-Clause
"""Per-client rate limiting: a token bucket per IP address, in memory.

Each address starts with `burst` tokens; a request takes one; tokens come
back at `rate` a second up to `burst`. The table is bounded: when it
holds `max_clients` addresses, those whose bucket has refilled (idle
clients, nothing to remember) are dropped, and if that frees nothing the
oldest half goes, so a flood of addresses costs memory but a bounded
amount."""
import time


class TokenBuckets:
    def __init__(self, rate, burst, max_clients=10000, clock=time.monotonic):
        self.rate = float(rate)
        self.burst = float(burst)
        self.max_clients = max_clients
        self.clock = clock
        self.buckets = {}  # address -> [tokens, time of the last update]

    def take(self, address):
        """(True, 0) if the request may go on, else (False, seconds until
        a token is back)."""
        now = self.clock()
        b = self.buckets.get(address)
        if b is None:
            if len(self.buckets) >= self.max_clients:
                self._prune(now)
            b = self.buckets[address] = [self.burst, now]
        tokens = min(self.burst, b[0] + (now - b[1]) * self.rate)
        b[1] = now
        if tokens >= 1.0:
            b[0] = tokens - 1.0
            return True, 0.0
        b[0] = tokens
        return False, (1.0 - tokens) / self.rate if self.rate > 0 else 60.0

    def _prune(self, now):
        full = [a for a, (t, last) in self.buckets.items()
                if t + (now - last) * self.rate >= self.burst]
        for a in full:
            del self.buckets[a]
        if len(self.buckets) >= self.max_clients:
            by_age = sorted(self.buckets, key=lambda a: self.buckets[a][1])
            for a in by_age[:len(by_age) // 2 + 1]:
                del self.buckets[a]
