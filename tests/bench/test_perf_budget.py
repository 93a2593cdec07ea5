# SPDX-License-Identifier: GPL-3.0-or-later
"""perf_budget.py: today's figures beside the kept ones, and keeping them."""
import json
import pathlib
import subprocess
import sys

SCRIPT = pathlib.Path(__file__).with_name("perf_budget.py")

BUDGET = {
    "kept_run": {"date": "2026-01-01", "commit": "abc1234", "seconds": "600", "load": "0.3"},
    "figures": [
        {"key": "cpu_one", "name": "one robot CPU", "unit": "%", "target": 1.5, "kept": 1.2, "noise": 0.2},
        {"key": "open_s", "name": "open a recording", "unit": "s", "target": 0.2, "kept": 0.19, "noise": 0.02},
        {"key": "rss", "name": "window RSS", "unit": "MiB", "kept": None, "noise": 10},
    ],
}

README = "# Project\n\n## Performance\n\n{begin}\nold table\n{end}\n\n## Licence\n"


def run(tmp_path, *args):
    budget = tmp_path / "budget.json"
    if not budget.exists():
        budget.write_text(json.dumps(BUDGET))
    return subprocess.run([sys.executable, str(SCRIPT), args[0], str(budget), *args[1:]],
                          capture_output=True, text=True)


def readme(tmp_path):
    sys.path.insert(0, str(SCRIPT.parent))
    import perf_budget
    path = tmp_path / "README.md"
    path.write_text(README.format(begin=perf_budget.README_BEGIN, end=perf_budget.README_END))
    return path


def test_a_figure_above_its_kept_value_by_more_than_its_noise_slid(tmp_path):
    result = run(tmp_path, "compare", "cpu_one=1.5", "open_s=0.19", "rss=80")
    assert result.returncode == 0, result.stderr
    assert "slid beyond their noise: one robot CPU\n" in result.stdout
    assert "missing their target: none" in result.stdout


def test_a_figure_within_its_noise_did_not_slide_and_one_above_its_target_misses_it(tmp_path):
    result = run(tmp_path, "compare", "cpu_one=1.3", "open_s=0.205")
    assert "slid beyond their noise: none" in result.stdout
    assert "missing their target: open a recording" in result.stdout


def test_a_figure_the_benchmark_did_not_print_is_shown_as_unknown_and_not_kept(tmp_path):
    path = readme(tmp_path)
    result = run(tmp_path, "keep", str(path), "cpu_one=", "open_s=0.1", "rss=71.5", "--seconds", "600")
    assert result.returncode == 0, result.stderr
    assert "no figure today" in result.stdout
    kept = json.loads((tmp_path / "budget.json").read_text())
    figures = {f["key"]: f for f in kept["figures"]}
    assert figures["cpu_one"]["kept"] == 1.2
    assert figures["open_s"]["kept"] == 0.1
    assert figures["rss"]["kept"] == 71.5
    assert kept["kept_run"] == {"seconds": "600"}


def test_keep_writes_readme_table_from_the_kept_figures(tmp_path):
    path = readme(tmp_path)
    result = run(tmp_path, "keep", str(path), "cpu_one=0.9", "open_s=0.12", "rss=70",
                 "--date", "2026-02-02", "--commit", "def5678", "--seconds", "600", "--load", "0.2 0.3 0.4")
    assert result.returncode == 0, result.stderr
    text = path.read_text()
    assert "old table" not in text
    assert "| one robot CPU | 0.9 % | 1.2 % | <= 1.5 % |" in text
    assert "| window RSS | 70 MiB | ? | - |" in text
    assert "Last kept run: 2026-02-02, commit def5678, 600 s runs" in text
    assert "The run before: 2026-01-01, commit abc1234" in text
    assert text.endswith("## Licence\n")


def test_keep_shows_the_run_before_beside_the_new_one(tmp_path):
    path = readme(tmp_path)
    result = run(tmp_path, "keep", str(path), "cpu_one=1.1", "open_s=0.15",
                 "--date", "2026-02-02", "--commit", "def5678", "--seconds", "600", "--load", "0.2")
    assert result.returncode == 0, result.stderr
    result = run(tmp_path, "keep", str(path), "cpu_one=1.0", "open_s=0.14",
                 "--date", "2026-02-03", "--commit", "fed8765", "--seconds", "600", "--load", "0.1")
    assert result.returncode == 0, result.stderr
    kept = json.loads((tmp_path / "budget.json").read_text())
    assert kept["run_before"]["commit"] == "def5678"
    text = path.read_text()
    assert "Last kept run: 2026-02-03, commit fed8765" in text
    assert "The run before: 2026-02-02, commit def5678" in text
    assert "| one robot CPU | 1 % | 1.1 % | <= 1.5 % |" in text
    assert "| window RSS | ? | ? | - |" in text  # never measured


def test_a_readme_without_the_table_markers_is_an_error_and_keeps_nothing(tmp_path):
    path = tmp_path / "README.md"
    path.write_text("# Project\n")
    result = run(tmp_path, "readme", str(path))
    assert result.returncode == 1
    assert "no performance table" in result.stderr
    assert path.read_text() == "# Project\n"


def test_a_budget_that_is_not_json_is_an_error(tmp_path):
    (tmp_path / "budget.json").write_text("{ not json")
    result = run(tmp_path, "compare", "cpu_one=1")
    assert result.returncode == 1
    assert "perf_budget.py:" in result.stderr
