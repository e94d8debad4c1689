"""The metro TCDS reference: train network of IEC 61375 (WTB between units, MVB inside a unit)."""
