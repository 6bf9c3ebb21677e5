# SPDX-License-Identifier: BSD-2-Clause
"""Set-up (waftools/deps.py) against what it promises (./waf check):

- no exact Debian version anywhere in the set-up code: a pin that the
  archive withdraws at its next point release stops every new machine;
- README's tables of Debian packages per target and per command say
  what set-up installs, and docs/contributing.md's list of the check's
  steps follows waftools/checks.py;
- a user who is not root gets one apt-get command with every missing
  package; a package older than a feature needs stops set-up with its
  name, the version found and the one needed; an upstream tarball that
  set-up does not know stops it with both checksums.
Nothing here installs or downloads anything.
"""
import io
import os
import re
import sys
import tempfile
import unittest
from unittest import mock

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from waftools import deps
from waftools.targets import MACHINES, TARGETS

# The files that install or name what gets installed.
SETUP_FILES = ["waftools/deps.py", "waftools/targets.py",
               "waftools/commands.py", "waftools/toolchains.py", "waf",
               "wscript", ".ci/run"]
# Debian version strings: an upstream version with a Debian revision
# (1.6+dfsg-3, 12.2.0-14), with an epoch (1:7.2+dfsg-7), a stable or
# security update's suffix (+deb12u18, ~deb13u1), a binNMU (+b3), and
# apt's pin syntax (pkg=1.2-3).
DEBIAN_VERSION = re.compile(
    r"\b\d+:\d[\w.+~]*-[\w.+~]+"
    r"|\b\d+(?:\.\d+)+[\w.+~]*-\d[\w.+~]*"
    r"|[+~]deb\d+u\d+"
    r"|\+b\d+\b"
    r"|\b[a-z0-9][a-z0-9+.-]+=\d[\w.+~:]*-[\w.+~]+")


def debian_versions(text):
    return [m.group(0) for m in DEBIAN_VERSION.finditer(text)]


def readme_table(header):
    """{first cell: [other cells]} of the README table under header, each
    cell a list of the `names` in it."""
    with open(os.path.join(TOP, "README.md")) as f:
        text = f.read()
    rows = {}
    for line in text[text.index(header):].splitlines()[2:]:
        if not line.startswith("|"):
            break
        cells = [re.findall(r"`([^`]+)`", c)
                 for c in line.strip("|").split("|")]
        rows[" ".join(cells[0])] = cells[1:]
    return rows


class NoVersionPins(unittest.TestCase):
    def test_the_scanner_finds_each_kind_of_pin(self):
        for pin in ['"qemu-system-ppc": "1:7.2+dfsg-7+deb12u18+b3"',
                    "apt-get install chromium=156.0.8078.108-1~deb12u1",
                    "MMDEBSTRAP_VERSION=1.3.5-7 mmdebstrap=1.3.5-7",
                    '"gcc": "4:12.2.0-3"', '"simavr": "1.6+dfsg-3"']:
            self.assertTrue(debian_versions(pin), pin)
        # what set-up may name: minimum versions and PyPI pins
        for fine in ['"qemu-system-arm": ("1:6.0", "mps2-an386")',
                     '"numpy==2.4.6"', "waflib-2.1.4-py2.py3-none-any.whl"]:
            self.assertEqual([], debian_versions(fine), fine)

    def test_no_debian_version_in_the_setup_code(self):
        for name in SETUP_FILES:
            with open(os.path.join(TOP, name)) as f:
                self.assertEqual([], debian_versions(f.read()), name)

    def test_package_names_are_bare_names(self):
        names = [p for group in deps.APT_GROUPS.values() for p in group]
        names += [p for t in list(TARGETS.values()) + list(MACHINES.values())
                  for p in t["packages"]]
        names += [p for r in deps.RELEASE_NAMES.values()
                  for p in list(r) + list(r.values())]
        names += [s["package"] for s in deps.SOURCES.values()]
        for p in names:
            self.assertRegex(p, r"^[a-z0-9][a-z0-9+.-]+$")

    def test_every_python_wheel_is_pinned_by_hash(self):
        for req, hashes in deps.PYTHON_PACKAGES.items():
            self.assertRegex(req, r"^[\w.-]+==[\w.]+$")
            self.assertTrue(1 <= len(hashes) <= len(deps.PYTHON_VERSIONS))
            for h in hashes:
                self.assertRegex(h, r"^[0-9a-f]{64}$")


class ReadmeTables(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.targets = readme_table("| target | to build | to run its images |")
        cls.commands = readme_table("| command | beyond its targets' packages |")

    def test_every_target_has_its_packages(self):
        listed = [t for key in self.targets for t in key.split()]
        self.assertEqual(sorted(TARGETS), sorted(listed))
        for key, (build, run) in self.targets.items():
            for name in key.split():
                t = TARGETS[name]
                machine = MACHINES[t["machine"]] if t["machine"] else {}
                self.assertEqual(deps.packages(t["packages"]), sorted(build),
                                 name)
                self.assertEqual(deps.packages(machine.get("packages", [])),
                                 sorted(run), name)

    def test_every_command_has_its_packages(self):
        extra = {"./waf check": ["check", "python"],
                 "./waf docs": ["docs", "python"],
                 "./waf bench": ["python"],
                 "./waf configure --rtems=...": ["rtems"]}
        for command, groups in extra.items():
            row = [k for k in self.commands if k.startswith(command)]
            self.assertEqual(1, len(row), command)
            self.assertEqual(deps.packages(groups=groups),
                             sorted(self.commands[row[0]][0]), command)


def check_list():
    """The numbered items of docs/contributing.md's "What ./waf check
    runs", each as one string."""
    with open(os.path.join(TOP, "docs", "contributing.md")) as f:
        text = f.read()
    section = text.split("## What `./waf check` runs", 1)[1].split("\n## ", 1)[0]
    items = []
    for line in section.splitlines():
        if re.match(r"^\d+\. ", line):
            items.append(line)
        elif items and line.startswith("   "):
            items[-1] += " " + line.strip()
    return items


class CheckSteps(unittest.TestCase):
    def test_the_list_follows_the_steps(self):
        sys.path.insert(0, os.path.join(TOP, ".deps", "waf"))  # waflib
        from waftools import checks
        items = check_list()
        self.assertEqual(len(checks.STEPS), len(items))
        for k, ((title, args, _), item) in enumerate(zip(checks.STEPS, items)):
            self.assertTrue(item.startswith("%d. " % (k + 1)), item)
            for path in checks.files(args):
                self.assertIn("`%s" % path, item, title)


class NotRoot(unittest.TestCase):
    def test_one_command_with_every_missing_package(self):
        wanted = deps.packages(TARGETS["ppc-e500"]["packages"]
                               + MACHINES["ppc-e500"]["packages"], ["check"])
        out = io.StringIO()
        with mock.patch.object(deps, "_is_root", lambda: False), \
                mock.patch.object(deps, "installed_version",
                                  lambda p: None), \
                mock.patch.object(deps, "_have_deb_src", lambda: False), \
                mock.patch.object(deps, "_source_ready", lambda s: False), \
                mock.patch.object(deps, "_known_tarball", lambda s: None), \
                mock.patch("sys.stdout", out):
            with self.assertRaises(deps.SetupError) as e:
                deps.ensure(wanted, ["unity"])
        text = str(e.exception)
        self.assertEqual(1, text.count("apt-get install"))
        command = text.split("apt-get install", 1)[1]
        for p in wanted:
            self.assertIn(" " + p, command)
        self.assertIn("deb-src", text)
        self.assertIn("--no-install-recommends", text)
        self.assertEqual("", out.getvalue())  # nothing tried


class Minimum(unittest.TestCase):
    def test_too_old_names_package_found_and_needed(self):
        with mock.patch.object(deps, "installed_version",
                               lambda p: "1:5.2+dfsg-11"):
            with self.assertRaises(deps.SetupError) as e:
                deps.check_minimum(["qemu-system-arm"])
        self.assertIn("qemu-system-arm 1:5.2+dfsg-11 is too old", str(e.exception))
        self.assertIn("1:6.0", str(e.exception))

    def test_new_enough_passes(self):
        for version in ("1:7.2+dfsg-7+deb12u18+b3", "1:10.0.13+ds-0+deb13u1"):
            with mock.patch.object(deps, "installed_version",
                                   lambda p, v=version: v):
                deps.check_minimum(["qemu-system-arm"])


class UnknownTarball(unittest.TestCase):
    def test_names_the_found_and_the_known_checksums(self):
        with tempfile.TemporaryDirectory() as tmp:
            def fake_source(cmd, cwd, **kw):
                with open(os.path.join(cwd, "libfixmath_0~20300101.orig.tar.xz"),
                          "wb") as f:
                    f.write(b"not the pinned tarball")
                return mock.Mock(stdout="", stderr="")
            with mock.patch.object(deps, "DEPS", tmp), \
                    mock.patch.object(deps._Apt, "update", lambda: None), \
                    mock.patch.object(deps.subprocess, "run", fake_source), \
                    mock.patch("sys.stdout", io.StringIO()):
                with self.assertRaises(deps.SetupError) as e:
                    deps.ensure_source("libfixmath")
        text = str(e.exception)
        self.assertIn("libfixmath_0~20300101.orig.tar.xz", text)
        import hashlib
        self.assertIn(hashlib.sha256(b"not the pinned tarball").hexdigest(),
                      text)
        for digest in deps.SOURCES["libfixmath"]["tarballs"]:
            self.assertIn(digest, text)


if __name__ == "__main__":
    unittest.main()
