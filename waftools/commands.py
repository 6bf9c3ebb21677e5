# SPDX-License-Identifier: BSD-2-Clause
"""waf tool: the commands beyond configure, build and install, and the
set-up each needs.

  ./waf demo    the default target: set up, build, run the demo firmware
  ./waf check   every target: set up, build, run every check and suite
  ./waf bench   the bench targets: instructions, footprint, stack
  ./waf docs    the API reference and the error plots of docs/accuracy.md
  ./waf fuzz    every libFuzzer target for --seconds each
  ./waf serve   the gold-standard service on 127.0.0.1:8080

Each installs what it needs and no more (waftools/deps.py): the packages
that build and run its targets, those of the groups it names, the
upstream sources and, where it runs Python tools, the Python packages;
then it configures its targets where the last configure left one out,
builds them and runs its internal command (run_<name>).
"""
import os
import subprocess
import sys

from waflib import Build, Context, Logs, Options, Scripting

from waftools import deps
from waftools.targets import DEFAULT_TARGET, MACHINES, TARGETS, with_role

# The upstream sources the images build with: Unity and libfixmath.
SOURCES = ("unity", "libfixmath")
OUT = "build"


def options(opt):
    opt.add_option("--seconds", type=int, default=60, dest="fuzz_seconds",
                   help="./waf fuzz: seconds per fuzzer (default 60)")


def packages(targets, run=False, groups=()):
    """Debian packages that build targets (and, if run, run their images),
    and those of the named groups of waftools/deps.py."""
    names = [p for n in targets for p in TARGETS[n]["packages"]]
    if run:
        names += [p for n in targets if TARGETS[n]["machine"]
                  for p in MACHINES[TARGETS[n]["machine"]]["packages"]]
    return deps.packages(names, groups)


def setup(ctx, pkgs, python=False):
    """Install pkgs, the upstream sources and, if python, the Python
    packages; return {source: folder, "python": folder or None}. Not
    root: stop with the one command that installs all of it."""
    try:
        return deps.ensure(pkgs, SOURCES, python)
    except deps.SetupError as e:
        ctx.fatal(str(e))


def python_path(ctx):
    """The folder of the pinned Python packages, installed if missing."""
    return setup(ctx, [], python=True)["python"]


def run_python(ctx, args, extra_env=None, **kw):
    """Run a Python tool of the project from its top folder, with the
    pinned Python packages where the command set them up."""
    env = dict(os.environ)
    env["PYTHONPATH"] = getattr(ctx, "python_path", "")
    env.update(extra_env or {})
    return subprocess.call([sys.executable] + args, cwd=ctx.path.abspath(),
                           env=env, **kw)


def run_now(commands):
    """Run waf commands within the current one, so that waf's closing
    "'<command>' finished successfully" follows the work."""
    for cmd in commands:
        Scripting.run_command(cmd)


def _configured():
    """(options, targets) of the last configure; (None, []) before the
    first."""
    from waflib import ConfigSet
    try:
        lock = ConfigSet.ConfigSet(os.path.join(Context.top_dir,
                                                Options.lockfile))
        cache = ConfigSet.ConfigSet(os.path.join(lock.out_dir, "c4che",
                                                 "_cache.py"))
    except (EnvironmentError, AttributeError):
        return None, []
    return lock.options, list(cache.TARGETS or [])


def configure_with(targets):
    """Configure where the last configure left out any of targets (or none
    ran), adding them to its targets and keeping its other options."""
    options, have = _configured()
    if options is not None and set(targets) <= set(have):
        return
    saved = Options.options.__dict__
    Options.options.__dict__ = dict(options or saved)
    Options.options.with_targets = ",".join(
        n for n in TARGETS if n in set(targets) | set(have))
    try:
        run_now(["configure"])
    finally:
        Options.options.__dict__ = saved


class Command(Context.Context):
    """A command on targets: set up, configure, build, then `then`."""
    cmd = None  # a base, not a command
    targets = []
    groups = []
    python = False
    then = None

    def execute(self):
        setup(self, packages(self.targets, run=True, groups=self.groups),
              self.python)
        configure_with(self.targets)
        run_now(["build_" + n for n in self.targets] + [self.then])


class Demo(Command):
    """build the default target and run the demo firmware under QEMU"""
    cmd = "demo"
    targets = [DEFAULT_TARGET]
    then = "run_demo"


class Check(Command):
    """build every target, then run every check and test suite"""
    cmd = "check"
    targets = list(TARGETS)
    groups = ["check"]
    python = True
    then = "run_checks"


class Bench(Command):
    """benchmark and footprint: build/bench/report.json, docs/performance.*"""
    cmd = "bench"
    targets = with_role("bench")
    python = True
    then = "run_bench"


class Docs(Command):
    """API reference (Doxygen) and the error plots of docs/accuracy.md"""
    cmd = "docs"
    targets = ["host"]
    groups = ["docs"]
    python = True
    then = "run_docs"


class Fuzz(Command):
    """run every libFuzzer target for --seconds each (tests/fuzz/)"""
    cmd = "fuzz"
    targets = with_role("fuzz")
    then = "run_fuzz"


class Serve(Command):
    """run the gold-standard web service on 127.0.0.1:8080 (docs/service.md)"""
    cmd = "serve"
    targets = ["host"]
    python = True
    then = "run_serve"


class Run(Build.BuildContext):
    """What a command runs after its builds: the configured environments
    restored, the Python packages' folder in python_path when python."""
    cmd = None  # a base, not a command
    variant = ""
    python = False

    def execute(self):
        self.restore()
        if not self.all_envs:
            self.load_envs()
        self.python_path = python_path(self) if self.python else ""
        self.run()


class RunDemo(Run):
    """(internal) run the demo image of the default target"""
    cmd = "run_demo"

    def run(self):
        t = TARGETS[DEFAULT_TARGET]
        img = os.path.join(OUT, DEFAULT_TARGET, "fw/demo/demo" + t["ext"])
        if run_python(self, ["qemu/harness.py", "show", t["machine"],
                             img]) != 0:
            self.fatal("demo failed")


class RunDocs(Run):
    """(internal) Doxygen into build/docs/html, plots into docs/img"""
    cmd = "run_docs"
    python = True  # matplotlib for the plots

    def run(self):
        if run_python(self, ["tools/gates/doxygen.py"]) != 0:
            self.fatal("Doxygen found undocumented or badly documented "
                       "symbols")
        Logs.info("API reference: build/docs/html/index.html")
        sampler = os.path.join(OUT, "host", "accuracy-sample")
        if run_python(self, ["tools/accuracy/plots.py", sampler,
                             "docs/img"]) != 0:
            self.fatal("accuracy plots failed")


class RunFuzz(Run):
    """(internal) run the fuzzers"""
    cmd = "run_fuzz"

    def run(self):
        if run_python(self, ["tools/gates/fuzz.py", "--build", OUT,
                             "--seconds",
                             str(Options.options.fuzz_seconds)]) != 0:
            self.fatal("fuzzing found something")


class RunBench(Run):
    """(internal) run the benchmark images and write the reports"""
    cmd = "run_bench"
    python = True  # matplotlib, for the chart

    def run(self):
        if run_python(self, ["tools/gates/bench.py", "--build", OUT, "--out",
                             os.path.join(OUT, "bench", "report.json"),
                             "--docs", "docs"]) != 0:
            self.fatal("benchmark failed")


class RunServe(Run):
    """(internal) pip install ./python into the build, run drdc.serve"""
    cmd = "run_serve"
    python = True  # aiohttp and numpy

    def run(self):
        site = os.path.join(OUT, "python", "serve-site")
        if run_python(self, ["-m", "pip", "install", "--quiet", "--no-index",
                             "--no-deps", "--disable-pip-version-check",
                             "--root-user-action=ignore", "--upgrade",
                             "--target", site,
                             os.path.join(self.path.abspath(), "python")]) != 0:
            self.fatal("pip install ./python failed")
        env = {"PYTHONPATH": os.pathsep.join([site, self.python_path])}
        args = os.environ.get("DRDC_SERVE_ARGS", "").split()
        try:
            run_python(self, ["-m", "drdc.serve"] + args, env)
        except KeyboardInterrupt:
            pass
