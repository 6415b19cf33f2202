#!/usr/bin/env python3
"""Downloads the source distribution of an OpenCV Python package from the package index pip uses
and checks its sha256 against the index link.

The sdist of opencv-contrib-python-headless carries the OpenCV sources (opencv/) and the contrib
modules (opencv_contrib/). `pip download` cannot fetch it alone: it runs the package's build step,
which builds all of OpenCV. So the file is read off the index page (PEP 503 simple API) instead.

Usage: fetch_sdist.py PACKAGE VERSION DEST_DIR
Prints the path of the verified archive. An archive already in DEST_DIR whose sha256 matches the
index is reused without downloading.
"""
import hashlib
import html.parser
import os
import re
import subprocess
import sys
import urllib.parse
import urllib.request


def index_url():
    """The index pip is configured with: PIP_INDEX_URL, then pip's config, then pip's default."""
    url = os.environ.get("PIP_INDEX_URL")
    if not url:
        try:
            url = subprocess.run([sys.executable, "-m", "pip", "config", "get", "global.index-url"],
                                 capture_output=True, text=True, check=True).stdout.strip()
        except (subprocess.CalledProcessError, OSError):
            url = ""
    if not url:
        try:
            from pip._internal.models.index import PyPI  # pip's built-in default index
        except ImportError:
            sys.exit("fetch_sdist: pip is not importable here; set PIP_INDEX_URL to the package index")
        url = PyPI.simple_url
    return url.rstrip("/") + "/"


class _Links(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.links = []  # (file name, href)
        self._href = None

    def handle_starttag(self, tag, attrs):
        if tag == "a":
            self._href = dict(attrs).get("href")

    def handle_data(self, data):
        if self._href is not None:
            self.links.append((data.strip(), self._href))
            self._href = None


def normalize(name):
    # PEP 503 project names, and sdist file names that use either '-' or '_' (PEP 625).
    return re.sub(r"[-_.]+", "-", name).lower()


def sha256_of(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    package, version, dest = sys.argv[1:]
    page_url = index_url() + normalize(package) + "/"
    with urllib.request.urlopen(page_url, timeout=120) as r:
        parser = _Links()
        parser.feed(r.read().decode("utf-8"))

    wanted = normalize(f"{package}-{version}.tar.gz")
    found = [(n, h) for n, h in parser.links if normalize(n) == wanted]
    if not found:
        sys.exit(f"fetch_sdist: no {package} {version} sdist on {page_url}")
    file_name, href = found[0]
    url = urllib.parse.urljoin(page_url, href)
    expected = urllib.parse.urlparse(url).fragment.partition("sha256=")[2]
    if not expected:
        sys.exit(f"fetch_sdist: the index gives no sha256 for {file_name}")

    os.makedirs(dest, exist_ok=True)
    path = os.path.join(dest, file_name)
    if os.path.exists(path) and sha256_of(path) == expected:
        print(path)
        return
    part = path + ".part"
    print(f"fetch_sdist: downloading {file_name}", file=sys.stderr)
    with urllib.request.urlopen(url.split("#")[0], timeout=600) as r, open(part, "wb") as f:
        while True:
            block = r.read(1 << 20)
            if not block:
                break
            f.write(block)
    got = sha256_of(part)
    if got != expected:
        os.remove(part)
        sys.exit(f"fetch_sdist: sha256 mismatch for {file_name}: got {got}, index says {expected}")
    os.replace(part, path)
    print(path)


if __name__ == "__main__":
    main()
