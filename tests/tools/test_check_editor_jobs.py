"""tools/check_editor_jobs.py: the real editor passes, and a made-up editor that starts or waits for a thread
outside the job abstraction is caught."""
import pathlib
import subprocess
import sys

REPO = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "tools"))
import check_editor_jobs  # noqa: E402


def write(root, path, text):
    file = root / "app" / "editor" / path
    file.parent.mkdir(parents=True, exist_ok=True)
    file.write_text(text)


def test_the_repository_editor_starts_and_waits_for_threads_only_in_its_jobs():
    result = subprocess.run([sys.executable, str(REPO / "tools/check_editor_jobs.py"), str(REPO)],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stdout


def test_the_job_abstraction_may_start_join_and_wait(tmp_path):
    write(tmp_path, "jobs/background_job.h", "std::thread t = std::thread([] {});\nvoid f() { t.join(); }\n")
    write(tmp_path, "jobs/thread_budget.cpp", "std::condition_variable c;\nvoid g() { c.wait(lock); }\n")
    write(tmp_path, "ui/panel.cpp", '// a comment may say join() and std::thread\nconst char* s = "wait()";\n')
    assert check_editor_jobs.check(str(tmp_path / "app" / "editor")) == []


def test_a_thread_started_or_waited_for_elsewhere_is_reported_with_its_line(tmp_path):
    write(tmp_path, "jobs/cage_maker.cpp", "int a;\nstd::thread worker(run);\n")
    write(tmp_path, "editor.cpp", "void shot() {\n  job.wait();\n  other.join();\n}\n")
    write(tmp_path, "model/scene_loading.cpp", "auto f = std::async(load);\n")
    problems = check_editor_jobs.check(str(tmp_path / "app" / "editor"))
    assert any(p.startswith("app/editor/jobs/cage_maker.cpp:2: starts a thread") for p in problems)
    assert any(p.startswith("app/editor/editor.cpp:2: waits for a thread") for p in problems)
    assert any(p.startswith("app/editor/editor.cpp:3: waits for a thread") for p in problems)
    assert any(p.startswith("app/editor/model/scene_loading.cpp:1: starts a thread") for p in problems)
    assert len(problems) == 4
