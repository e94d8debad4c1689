"""Chinese values in Chinese step phrasings (`# language: zh-CN` features): the step library's functions take
the English values the driver interface knows, so a Chinese sentence's words are converted first."""
from __future__ import annotations

DIRECTIONS = {"前进": "forward", "向前": "forward", "后退": "reverse", "向后": "reverse", "中立": "neutral",
              "零位": "neutral"}
FRAMES = {"状态": "status", "命令": "command", "令牌": "token", "块": "block"}


def direction(word: str) -> str:
    return DIRECTIONS.get(word, word)


def frame(word: str) -> str:
    return FRAMES.get(word, word)
