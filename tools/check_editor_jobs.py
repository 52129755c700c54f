#!/usr/bin/env python3
"""The editor's job rule (docs/editor.md, "Jobs and thread budgets"): in app/editor only the job abstraction
(jobs/background_job.h, .cpp) starts threads, and nothing outside the job side waits for one: no join(), no wait()
and no condition variable but the job's own (a superseded job joined by the next job's thread, the destructor at
exit) and the thread budget's (job threads waiting for cores). The UI thread polls. Prints each violation with
file:line and exits 1 when there is one.

Usage: check_editor_jobs.py [REPOSITORY_ROOT]
"""
import os
import re
import sys

STARTS_THREAD = re.compile(r"\bstd::(jthread|thread|async)\b|\bpthread_create\b")
WAITS = re.compile(r"\.\s*(join|wait|wait_for|wait_until)\s*\(|\bstd::condition_variable\b")
MAY_START = {"jobs/background_job.h", "jobs/background_job.cpp"}
MAY_WAIT = {"jobs/background_job.h", "jobs/thread_budget.h", "jobs/thread_budget.cpp"}
SOURCE = re.compile(r"\.(h|cpp)$")


def code(line):
    """The line without its // comment and the contents of its string literals."""
    line = re.sub(r'"(\\.|[^"\\])*"', '""', line)
    return line.split("//", 1)[0]


def check(editor):
    """The violations in the editor folder `editor`, as 'file:line: problem' strings."""
    problems = []
    for folder, _, names in sorted(os.walk(editor)):
        for name in sorted(names):
            if not SOURCE.search(name):
                continue
            path = os.path.join(folder, name)
            key = os.path.relpath(path, editor).replace(os.sep, "/")
            with open(path, encoding="utf-8") as source:
                for number, line in enumerate(source, 1):
                    text = code(line)
                    if STARTS_THREAD.search(text) and key not in MAY_START:
                        problems.append(f"app/editor/{key}:{number}: starts a thread; run the work as a "
                                        "BackgroundJob (jobs/background_job.h)")
                    if WAITS.search(text) and key not in MAY_WAIT:
                        problems.append(f"app/editor/{key}:{number}: waits for a thread; poll the job (busy, "
                                        "ready, poll) when its wake-up arrives")
    return problems


if __name__ == "__main__":
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    found = check(os.path.join(root, "app", "editor"))
    for problem in found:
        print(problem)
    print(f"editor jobs: {len(found)} problem(s)" if found else "editor jobs: ok")
    sys.exit(1 if found else 0)
