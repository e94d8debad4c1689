"""The CRH2 reference train (profile `crh2`): the ring, its CCU/LCU nodes, the vehicle and its interlocks."""
