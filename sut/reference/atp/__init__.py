"""The train-control interface reference (profile `atp`): the CTCS3-300T VDX emergency-brake interface (seed
003) and the CTCS-2 200C on-board ATP functions (seed 001)."""
