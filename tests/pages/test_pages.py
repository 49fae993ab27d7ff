"""test_pages.py - the report pages of `ggx demo`, `bench`, `stress` and
`converge` in a real browser: headless Chromium (SwiftShader's WebGL, no GPU)
driven through Selenium's WebDriver with Debian's /usr/bin/chromedriver, each
page opened from the file system.  A page fails on any console error or
failed request (Chromium logs both as SEVERE), on an image that does not
load, and, for the demo, on a 3-D view that draws nothing or draws the same
picture for two methods.  Negative controls: a page with a missing script,
a missing image and a thrown error is caught by the same checks, and without
WebGL the demo says so in place of each view.  Needs GGX_BINARY (the ggx
tool), chromium and chromium-driver."""
import os
import shutil
import subprocess

import pytest
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By

GGX = os.environ["GGX_BINARY"]

# Per canvas: its element's id, how many pixels are not the white background, and a hash of them.
FINGERPRINTS = """
return Array.from(document.querySelectorAll('.cloud canvas')).map(function (canvas) {
  var copy = document.createElement('canvas');
  copy.width = canvas.width; copy.height = canvas.height;
  var g = copy.getContext('2d');
  g.drawImage(canvas, 0, 0);
  var d = g.getImageData(0, 0, copy.width, copy.height).data, drawn = 0, hash = 0;
  for (var i = 0; i < d.length; i += 4)
    if (d[i] < 250 || d[i + 1] < 250 || d[i + 2] < 250) {
      ++drawn;
      hash = (hash * 31 + d[i] + 7 * d[i + 1] + 13 * d[i + 2] + i) % 1000000007;
    }
  return [canvas.closest('.cloud').id, drawn, hash];
});
"""
BROKEN_IMAGES = "return Array.from(document.images).filter(i => !(i.complete && i.naturalWidth > 0))" \
                ".map(i => i.getAttribute('src'))"


def ggx(*args):
    result = subprocess.run([GGX, *map(str, args)], capture_output=True, text=True)
    assert result.returncode == 0, f"ggx {' '.join(map(str, args))}: {result.stderr[-2000:]}"


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    out = tmp_path_factory.mktemp("pages")
    for folder in ("bench", "stress", "converge"):
        (out / folder).mkdir()
    ggx("demo", "--out", out / "demo", "-n", 4096, "--histogram-n", "1e5", "--page-points", 3000)
    ggx("bench", "--methods", "caps,heitz", "--precisions", "precise", "--jobs", "write,furnace", "-n", "2^16",
        "--native-count", "2^14", "--repeats", 5, "--scene", 2, "--cell-samples", "2^10", "--no-startup",
        "--html", out / "bench" / "bench.html")
    ggx("stress", "--methods", "caps,ndf", "--out", out / "stress" / "map", "--html", out / "stress" / "stress.html")
    ggx("converge", "--methods", "caps,heitz", "--max-n", 1024, "--randomizations", 8,
        "--html", out / "converge" / "converge.html")
    return out


def browser(*extra):
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for argument in ("--headless=new", "--no-sandbox", "--enable-unsafe-swiftshader", "--window-size=1200,900",
                     "--disable-dev-shm-usage", *extra):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)


@pytest.fixture(scope="module")
def chromium():
    driver = browser()
    yield driver
    driver.quit()


def problems(driver, path):
    """Opens `path` from the file system: its console errors and failed requests, and its broken images."""
    driver.get_log("browser")  # what earlier pages left
    driver.get("file://" + str(path))
    errors = [entry["message"] for entry in driver.get_log("browser") if entry["level"] == "SEVERE"]
    return errors, driver.execute_script(BROKEN_IMAGES)


@pytest.mark.parametrize("page, images", [("demo/index.html", 6), ("bench/bench.html", 2),
                                          ("stress/stress.html", 2), ("converge/converge.html", 4)])
def test_a_page_opens_offline_without_errors(pages, chromium, page, images):
    errors, broken = problems(chromium, pages / page)
    assert errors == []
    assert broken == []
    assert len(chromium.find_elements(By.TAG_NAME, "img")) >= images
    assert len(chromium.find_elements(By.TAG_NAME, "table")) >= 1


def test_every_method_draws_its_own_cloud(pages, chromium):
    problems(chromium, pages / "demo" / "index.html")
    prints = chromium.execute_script(FINGERPRINTS)
    assert [p[0] for p in prints] == ["cloud-" + m for m in ("ndf", "heitz", "heitz2017", "caps", "caps-iso",
                                                             "bounded")]
    for name, drawn, _ in prints:
        assert drawn > 2000, f"{name}: {drawn} pixels drawn"
    assert len({p[2] for p in prints}) == len(prints), "two methods drew the same picture"
    caps = chromium.find_element(By.ID, "cloud-caps")
    caps.find_element(By.CSS_SELECTOR, "button[data-show=m]").click()
    after = {p[0]: p[2] for p in chromium.execute_script(FINGERPRINTS)}
    assert after["cloud-caps"] != dict((p[0], p[2]) for p in prints)["cloud-caps"], "m drew what o drew"
    assert [e for e in chromium.get_log("browser") if e["level"] == "SEVERE"] == []


def test_the_checks_catch_a_broken_page(pages, chromium, tmp_path):
    broken = tmp_path / "demo"
    shutil.copytree(pages / "demo", broken)
    (broken / "three" / "three.min.js").unlink()
    (broken / "caps.hist.png").unlink()
    with open(broken / "index.html", "a") as page:
        page.write("<script>throw new Error('a deliberate error');</script>\n")
    errors, images = problems(chromium, broken / "index.html")
    assert any("three.min.js" in e and "ERR_FILE_NOT_FOUND" in e for e in errors)
    assert any("a deliberate error" in e for e in errors)
    assert images == ["caps.hist.png"]
    notes = chromium.find_elements(By.CSS_SELECTOR, ".cloud .no-webgl")
    assert len(notes) == 6 and "three.js" in notes[0].text


def test_without_webgl_the_page_says_so(pages):
    driver = browser("--disable-3d-apis")
    try:
        errors, images = problems(driver, pages / "demo" / "index.html")
        assert errors == [] and images == []
        notes = driver.find_elements(By.CSS_SELECTOR, ".cloud .no-webgl")
        assert len(notes) == 6 and "no WebGL" in notes[0].text
        assert driver.find_elements(By.CSS_SELECTOR, ".cloud canvas") == []
    finally:
        driver.quit()
