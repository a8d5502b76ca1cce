/* The registers a shading unit loads for one span, per channel (kernels/units/<unit>.h say which it uses):
 * S at the span's left pixel, E at its right one (the counter's right start, or the sierpinski copy's adder
 * constant), the increment dI, interleave:M:own's own-rounded M*dI, and the sierpinski copy's direction. */
#ifndef PARASHADE_SPAN_REGISTERS_H
#define PARASHADE_SPAN_REGISTERS_H

typedef struct {
  int start[3], end[3], step[3], lane_step[3];
  int sign;
} SpanRegisters;

#endif
