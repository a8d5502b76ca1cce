// The segment-parallel unit (docs/hardware.md): P pixels per clock (P a power of two). The base
// register holds the segment's first pixel; output i is base + i*dI (P - 1 output adders) from the
// multiples of the dI register (ps_multiples: wired shifts, one adder per odd multiple); the base steps
// by P*dI (one accumulating adder). Outputs past the span's end are blocked.
/* verilator lint_off UNUSEDSIGNAL */
module ps_segment #(
  parameter I = 12,
  parameter F = 12,
  parameter LEN = 13,
  parameter P = 4
) (
  input  wire             clk,
  input  wire             rst,
  input  wire             load,
  output wire             ready,
  input  wire [I+F-1:0]   s_in,
  input  wire [I+F-1:0]   e_in,
  input  wire [I+F-1:0]   step_in,
  input  wire [I+F-1:0]   lane_step_in,
  input  wire [LEN-1:0]   length_in,
  output wire [P-1:0]     valid,
  output wire [P*LEN-1:0] x,
  output wire [P*(I+F)-1:0] value,
  output wire [P*8-1:0]   level
);
  localparam W = I + F;
  /* verilator lint_off WIDTH */  // the lane counts, truncated to the length's bits
  localparam [LEN-1:0] LANES = P;  // pixels per clock
  /* verilator lint_on WIDTH */
  reg [W-1:0] base, step;
  reg [LEN-1:0] first, rest;
  reg busy;
  wire [(P+1)*W-1:0] mult;
  ps_multiples #(.W(W), .N(P)) multiples (.step(step), .mult(mult));
  assign ready = !busy && !rst;  // in reset `load` is ignored: never offer to take it
  always @(posedge clk) begin
    if (rst) begin
      busy <= 1'b0;
    end else if (load && ready) begin
      base <= s_in;
      step <= step_in;
      first <= {LEN{1'b0}};
      rest <= length_in;
      busy <= 1'b1;
    end else if (busy) begin
      base <= base + mult[P*W +: W];
      first <= first + LANES;
      rest <= rest - LANES;
      busy <= rest > LANES;
    end
  end
  genvar i;
  generate
    for (i = 0; i < P; i = i + 1) begin : out
      /* verilator lint_off WIDTH */
      localparam [LEN-1:0] K = i;  // the output's pixel after `first`
      /* verilator lint_on WIDTH */
      wire [W-1:0] v;
      if (i == 0) begin : pass
        assign v = base;
      end else begin : add
        assign v = base + mult[i*W +: W];
      end
      assign valid[i] = busy && rest > K;
      assign x[i*LEN +: LEN] = first + K;
      assign value[i*W +: W] = v;
      ps_level #(.I(I), .F(F)) level_i (.v(v), .level(level[i*8 +: 8]));
    end
  endgenerate
endmodule
