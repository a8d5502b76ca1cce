/* The modeled shading units (docs/units.md), shared by the host (UnitKind takes their ids; cost models,
 * golden-model tests, planning) and the kernels (which count the clocks of the spans they shade): one
 * header per unit in units/, with its id, its clocks per span and, for the kernels, its register closed
 * form. The build lists them (cmake/unit_kinds.cmake): units/all.h for the kernels,
 * parashade/unit_kinds.hpp for the host. */
#ifndef PARASHADE_UNIT_COST_H
#define PARASHADE_UNIT_COST_H

/* Clocks to load a span's registers (the edge step of the line interpolators and the loads run in
 * parallel: one clock), before the span's pixels (pipelined.h overlaps it with the previous span). */
#define SPAN_LOAD_CLOCKS 1

#ifdef __OPENCL_VERSION__
#include "units/all.h"
#endif

#endif
