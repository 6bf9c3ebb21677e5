# SPDX-License-Identifier: BSD-2-Clause
"""python -m drdc.serve: run the service (docs/service.md).

It refuses to run as root unless --allow-root says so: the service reads
no file and runs no command from its input, but an unprivileged account
limits what a defect in it, aiohttp or the library could reach. It does
not drop privileges itself (that would need a user to switch to and
code that is easy to get wrong): start it as such a user."""
import argparse
import json
import logging
import os
import sys

MISSING = ("drdc.serve needs aiohttp, which is not installed: pip install "
           "'drdc[serve]' (the serve extra of the drdc package), or, where "
           "the package was installed with --target, aiohttp into the same "
           "place")


def _missing_aiohttp(e):
    """Whether an ImportError is aiohttp's absence (not a defect of ours):
    the message of the extra to install instead of a traceback."""
    return isinstance(e, ImportError) and (e.name or "").split(".")[0] in (
        "aiohttp", "multidict", "yarl", "frozenlist", "aiosignal",
        "propcache", "aiohappyeyeballs", "attr", "idna")


def main(argv=None):
    try:
        return _main(argv)
    except ImportError as e:
        if not _missing_aiohttp(e):
            raise
        print("%s (%s)" % (MISSING, e), file=sys.stderr)
        return 1


def _main(argv=None):
    from aiohttp import web

    from .app import Limits, make_app
    from .openapi import document

    d = Limits()
    ap = argparse.ArgumentParser(prog="python -m drdc.serve",
                                 description=__doc__,
                                 formatter_class=argparse.
                                 RawDescriptionHelpFormatter)
    ap.add_argument("--host", default="127.0.0.1",
                    help="address to listen on (default 127.0.0.1)")
    ap.add_argument("--port", type=int, default=8080)
    ap.add_argument("--body-bytes", type=int, default=d.body_bytes,
                    help="request body cap (default %(default)s)")
    ap.add_argument("--batch", type=int, default=d.batch,
                    help="elements of one /v1/eval (default %(default)s)")
    ap.add_argument("--rate", type=float, default=d.rate,
                    help="requests a second per client address "
                         "(default %(default)s)")
    ap.add_argument("--burst", type=float, default=d.burst,
                    help="token bucket size per client (default "
                         "%(default)s)")
    ap.add_argument("--timeout", type=float, default=d.timeout,
                    help="seconds for one request (default %(default)s)")
    ap.add_argument("--allow-root", action="store_true",
                    help="run even as root (a throwaway container only)")
    ap.add_argument("--openapi", action="store_true",
                    help="print the OpenAPI document of these limits and "
                         "exit")
    args = ap.parse_args(argv)
    limits = Limits(body_bytes=args.body_bytes, batch=args.batch,
                    rate=args.rate, burst=args.burst, timeout=args.timeout)
    if args.openapi:
        json.dump(document(limits), sys.stdout, indent=1, sort_keys=True)
        sys.stdout.write("\n")
        return 0
    if hasattr(os, "geteuid") and os.geteuid() == 0 and not args.allow_root:
        print("drdc.serve: refusing to run as root; start it as an "
              "unprivileged user (docs/service.md), or pass --allow-root",
              file=sys.stderr)
        return 2
    logging.basicConfig(level=logging.INFO, format="%(asctime)s %(message)s")
    web.run_app(make_app(limits), host=args.host, port=args.port,
                access_log=None, print=lambda s: print(s, flush=True))
    return 0


if __name__ == "__main__":
    sys.exit(main())
