/* The pipelined:M unit (docs/units.md, docs/hardware.md "Pipelined"): interleave:M's M code
 * interpolators (lane j from S + j*dI, stepping by the shifted and added M*dI) with double-buffered span
 * registers: the next span's load clock overlaps the current span's clocks, so a span takes ceil(L/M)
 * clocks in all, its load included (hw/ps_pipelined.v; filling the pipeline costs 2 clocks once per unit,
 * which the model leaves out). Every span is charged SPAN_LOAD_CLOCKS, so its span clocks are the
 * rest: ceil(L/M) - SPAN_LOAD_CLOCKS. Its registers hold classic's S + i*dI (unit_registers.h's default).
 * Golden model, cost and error bound: host/units/pipelined.cpp. */
#ifndef PARASHADE_UNIT_PIPELINED_H
#define PARASHADE_UNIT_PIPELINED_H

#include "../fixed_point.h"
#include "../unit_cost.h" /* SPAN_LOAD_CLOCKS */

#define UNIT_PIPELINED 5

/* Clocks of a span of `length` >= 1 pixels beyond the load clock it is charged, `lanes` = M. */
PS_INLINE ps_int pipelined_span_clocks(int lanes, ps_int length) {
  return (length + lanes - 1) / lanes - SPAN_LOAD_CLOCKS;
}

#if defined(UNIT_KIND) && UNIT_KIND == UNIT_PIPELINED /* the kernel's unit (unit_registers.h) */
#define UNIT_SPAN_CLOCKS pipelined_span_clocks
#endif

#endif
