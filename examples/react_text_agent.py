"""A ReAct-style text agent (Yao et al., 2023) for `luminous eval --mode text`, whose language model is yours:
`make_react(llm)` takes any `llm(prompt: str) -> str` and returns the agent's `act(observation, admissible)`.
Nothing is downloaded; `act` below plugs in `keyword_llm`, a stand-in "model" that reads the task and prefers
commands naming its words, so the loop runs anywhere:

    luminous eval --mode text --policy examples.react_text_agent:act --split U+ --episodes 20 --out OUT

Replace `keyword_llm` by a call to your model (its reply must end in "Action: <command>")."""

from __future__ import annotations

import random
import re
from collections.abc import Callable

WELCOME = "-= Welcome to TextWorld, ALFRED! =-"
PROMPT = ("You are in a household. Think step by step, then give one command from the admissible list.\n"
          "Answer as 'Think: ...' then 'Action: <command>'.\n\n")


def make_react(llm: Callable[[str], str], memory: int = 30) -> Callable[[str, list[str]], str]:
    """A text agent: the episode so far (task, thoughts, actions, observations) in the prompt, one command out."""
    history: list[str] = []

    def act(observation: str, admissible: list[str]) -> str:
        if observation.startswith(WELCOME):  # a new episode
            history.clear()
        history.append(f"Observation: {observation}")
        prompt = PROMPT + "\n".join(history[-memory:]) + "\nAdmissible: " + "; ".join(admissible) + "\n"
        reply = llm(prompt)
        history.append(reply.strip())
        action = reply.rsplit("Action:", 1)[-1].strip().splitlines()[0] if "Action:" in reply else ""
        return action if action in admissible else "look"

    return act


def keyword_llm(prompt: str) -> str:
    """A stand-in for a language model: the admissible command sharing most words with the task (ties broken by
    a hash of the prompt, so the same prompt gives the same reply)."""
    task = re.search(r"Your task is to: (.*)\.", prompt)
    words = set(task.group(1).split()) if task else set()
    admissible = prompt.rsplit("Admissible: ", 1)[1].strip().split("; ")
    rng = random.Random(len(prompt))
    best = max(admissible, key=lambda c: (len(words & set(c.split())) - (c in prompt), rng.random()))
    return f"Think: the task names {sorted(words)}.\nAction: {best}"


act = make_react(keyword_llm)
