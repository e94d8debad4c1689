"""The implementer's contract: per profile, what any SUT must expose for the suite to test it
(`<profile>.yaml` beside this file), and the guard that holds the steps to it (guard.py)."""
from sut.contract.catalogue import Contract, ContractBreach, ContractFileError, ContractGap, load

__all__ = ["Contract", "ContractBreach", "ContractFileError", "ContractGap", "load"]
