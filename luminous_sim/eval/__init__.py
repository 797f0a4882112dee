"""Layer L5: evaluation on LUMINOUS's splits (S+, U+, U+test) with ALFRED's metrics and limits.

A policy (`oracle`, `random`, or a user's agent as `MODULE:CALLABLE`, run in a child process with time and
memory limits: `AgentLimits`; see docs/evaluation.md) plays episodes of a split; SR, GC, PLW-SR and PLW-GC
come out overall and per task type, as JSON, a markdown table in the layout of the paper's Table 4, and a plot.

Typical use::

    from luminous_sim.eval import evaluate, write_reports
    report = evaluate("oracle", "U+", 14, workers=2)
    with make_backend("ray", workers=2) as backend:          # from luminous_sim.data: Ray workers
        report = evaluate("oracle", "U+", 14, backend=backend)
    print(report.overall.sr, report.per_type["pick_and_place_simple"].gc)
    write_reports(report, Path("out/eval"))
"""

from luminous_sim.eval.evaluator import (
    EVAL_ENV,
    EpisodeJob,
    EvalReport,
    check_output,
    crashed_build,
    data_run,
    evaluate,
    evaluate_data,
    play,
    run_job,
)
from luminous_sim.eval.metrics import EpisodeOutcome, Metrics, metrics, metrics_by_type, type_average
from luminous_sim.eval.policies import (
    BUILT_IN,
    Agent,
    AgentContext,
    PolicyError,
    ReplayAgent,
    TextAgentContext,
    check_policy,
    make_agent,
    resolve_factory,
)
from luminous_sim.eval.report import TABLE4_ROWS, markdown_table, plot, write_reports
from luminous_sim.eval.sandbox import AgentCrashed, AgentLimits, AgentProcess, AgentTimeout
from luminous_sim.eval.text_eval import TEXT_BUILT_IN, TextOutcome, TextReport, evaluate_text, play_text
from luminous_sim.eval.tracks import AGENT_INFO, PRIVILEGED_OPTIONS, TRACKS, agent_info, track_env
from luminous_sim.eval.trials import TrialRef, list_trials
from luminous_sim.eval.workers import map_local, map_ordered

__all__ = [
    "AGENT_INFO",
    "BUILT_IN",
    "EVAL_ENV",
    "PRIVILEGED_OPTIONS",
    "TABLE4_ROWS",
    "TEXT_BUILT_IN",
    "TRACKS",
    "Agent",
    "AgentContext",
    "AgentCrashed",
    "AgentLimits",
    "AgentProcess",
    "AgentTimeout",
    "EpisodeJob",
    "EpisodeOutcome",
    "EvalReport",
    "Metrics",
    "PolicyError",
    "ReplayAgent",
    "TextAgentContext",
    "TextOutcome",
    "TextReport",
    "TrialRef",
    "agent_info",
    "check_output",
    "check_policy",
    "crashed_build",
    "data_run",
    "evaluate",
    "evaluate_data",
    "evaluate_text",
    "list_trials",
    "make_agent",
    "map_local",
    "map_ordered",
    "markdown_table",
    "metrics",
    "metrics_by_type",
    "play",
    "play_text",
    "plot",
    "resolve_factory",
    "run_job",
    "track_env",
    "type_average",
    "write_reports",
]
