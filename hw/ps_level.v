// The 8-bit output level of an I.F span register: round to nearest, ties up, then saturate to
// [0, 255] (kernels/fixed_point.h, register_level). One adder of I + 1 bits and two comparisons.
module ps_level #(
  parameter I = 12,  // integer bits, sign included (>= 9)
  parameter F = 12   // fraction bits (>= 1)
) (
  input  wire [I+F-1:0] v,
  output wire [7:0]     level
);
  // v >> F (arithmetic), widened by one bit so that adding the rounding bit cannot overflow.
  wire signed [I:0] whole = {v[I+F-1], v[I+F-1:F]};
  wire signed [I:0] r = whole + $signed({{I{1'b0}}, v[F-1]});
  // Negative: 0; a one among bits I-1..8 of a non-negative r: above 255.
  assign level = r[I] ? 8'd0 : (|r[I-1:8] ? 8'd255 : r[7:0]);
endmodule
