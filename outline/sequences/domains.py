"""The values a random sequence may give each stimulus of a profile, where the contract names a stimulus but
not its range: the cabs a desk has, the numbers an input takes. The ranges span the features' own values and
beyond (an input the features set to 0-300 km/h is drawn from 0-350), so a sequence reaches both sides of
every band the requirements give."""
from __future__ import annotations

# Cabs are numbered by their car (the contracts' `about`): the two ends of the set.
CABS = {"crh2": (1, 8), "atp-crh2": (1, 8), "metro-tcn": (1, 6)}
CARS = {"crh2": 8, "atp-crh2": 8, "metro-tcn": 6}
# Supplies where the SUT does not list them (supplies()): the VDX's own input.
SUPPLIES = {"vdx": ("VDX",)}
SUPPLY_VOLTS = (0.0, 160.0)             # both sides of 70-125 % of 110 V and of the CRH2 supply bands
RECORD_UNITS = {"metro-tcn": ("car1.CCU", "car6.CCU"), "atp": ("ATP",)}
# A number input's range by its unit (the contract gives the unit); an input without one is left out.
NUMBER_RANGES = {"km/h": (0.0, 350.0), "kPa": (0.0, 900.0), "% of demand": (0.0, 120.0), "%": (0.0, 100.0),
                 "m": (0.0, 5000.0), "V": (0.0, 160.0), "mV": (0.0, 1000.0)}
# Desk controls: notches and steps the contracts give (set_traction 0..10, set_brake 0..8).
TRACTION_NOTCHES = range(0, 11)
BRAKE_STEPS = range(0, 9)
DIRECTIONS = ("neutral", "forward", "reverse")
# How long time runs between stimuli (us): a millisecond at a time, where relays and pulses are judged (3, 6,
# 8 ms), a poll, a cycle, a supervision bound, a long wait. The observables are looked at after each.
ADVANCES_US = (1_000, 2_000, 3_000, 5_000, 10_000, 50_000, 120_000, 500_000, 2_000_000, 10_000_000)
# Long runs (soak), one time passing in SOAK_ODDS + 1: half a minute to ten, sampled once at the end or every
# 10 s or 1 min (a crh2 set soaks ten minutes in ~1 s of CPU; a mutant that keeps a backend from skipping costs
# ten minutes frame by frame, ~30 s).
SOAKS_US = (30_000_000, 120_000_000, 600_000_000)
SOAK_SAMPLES_US = (None, 10_000_000, 60_000_000)
SOAK_ODDS = 7
# Integer inputs by unit: a digital input without one is 0/1; an analogue raw count spans 0..100 %.
INTEGER_RANGES = {None: (0, 1), "Hz": (1650, 2650)}
RAW_COUNT = (0, 10_000)
# ZPW-2000 carriers (Hz): drawn half the time, so a carrier the ATP knows is not left to chance.
CARRIERS = (1700, 2000, 2300, 2600)

# The metro's buses and its two units of three cars (TCN-02, TCN-04: one MVB per unit, the WTB between them).
METRO_BUSES = ("WTB", "unit1.MVB", "unit2.MVB")
METRO_UNIT_CARS = {1: (1, 2, 3), 2: (4, 5, 6)}


def car_of(name: str) -> int:
    """The car a metro name is in (`car4.VVVF` -> 4)."""
    return int(name.split(".", 1)[0].removeprefix("car"))


# The ATP's line on the rig (absolute metres): the track circuits a balise describes (start, end, carrier; down-line
# carriers, ATP-04), the ends of authority it gives (inside the first circuit, so a train running up to one under
# the opening's carrier stays consistent, ATP-02), the stop points of precise-positioning balises; the
# low-frequency codes the signal generator sends.
ATP_LINE = ((0, 2000, 1700), (2000, 4000, 2300))
ATP_EOAS = (1200, 1800)
ATP_STOPS = (800, 1500)
ATP_CODES = ("L", "L2", "LU", "U")
# The CFSK's carrier sets (ATP-04; ZPW-2000: the contract's `CFSK carrier set`).
ATP_CARRIER_SETS = {"down": (1700, 2300), "up": (2000, 2600)}
