/* The modeled shading units (docs/units.md), shared by the host (UnitKind takes their ids; cost models,
 * golden-model tests, planning) and the kernels (which count the clocks of the spans they shade): one
 * header per unit, with its id, its clocks per span and, for the kernels, its register closed form. */
#ifndef PARASHADE_UNIT_COST_H
#define PARASHADE_UNIT_COST_H

/* Clocks to load a span's registers (the edge step of the line interpolators and the loads run in
 * parallel: one clock), before the span's pixels (pipelined.h overlaps it with the previous span). */
#define SPAN_LOAD_CLOCKS 1

#include "units/classic.h"
#include "units/counter.h"
#include "units/interleave.h"
#include "units/segment.h"
#include "units/pipelined.h"
#include "units/sierpinski.h"

#endif
