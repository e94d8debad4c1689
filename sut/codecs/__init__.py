"""Frame codecs of the standards the trains use, shared by the reference (which speaks them) and the step
library (whose bus analyser checks frames on the wire against them): not reference internals."""
