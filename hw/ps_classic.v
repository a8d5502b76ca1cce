// The classic unit (docs/hardware.md): one code interpolator. A load clock takes the span's registers
// S and dI (already rounded to I.F by setup) and its length; then one pixel per clock: S, S + dI, ...
// through one W-bit wrapping adder, the row interpolator giving each pixel's offset x.
// Interface shared by every unit in hw/ (lanes = 1 here): `ready` high = `load` is taken this clock.
/* verilator lint_off UNUSEDSIGNAL */
module ps_classic #(
  parameter I = 12,
  parameter F = 12,
  parameter LEN = 13  // bits of a span length (1..2^LEN - 1 pixels; 13 holds 4096)
) (
  input  wire             clk,
  input  wire             rst,
  input  wire             load,
  output wire             ready,
  input  wire [I+F-1:0]   s_in,          // S: the register at the span's left pixel
  input  wire [I+F-1:0]   e_in,          // E (counter only)
  input  wire [I+F-1:0]   step_in,       // dI
  input  wire [I+F-1:0]   lane_step_in,  // M*dI rounded on its own (interleave OWN only)
  input  wire [LEN-1:0]   length_in,     // pixels, >= 1
  output wire [0:0]       valid,
  output wire [LEN-1:0]   x,             // pixel offset from the span's left pixel
  output wire [I+F-1:0]   value,         // the register
  output wire [7:0]       level
);
  localparam W = I + F;
  reg [W-1:0] acc, step;
  reg [LEN-1:0] xr, last;
  reg busy;
  assign ready = !busy && !rst;  // in reset `load` is ignored: never offer to take it
  always @(posedge clk) begin
    if (rst) begin
      busy <= 1'b0;
    end else if (load && ready) begin
      acc <= s_in;
      step <= step_in;
      xr <= {LEN{1'b0}};
      last <= length_in - 1'b1;
      busy <= 1'b1;
    end else if (busy) begin
      acc <= acc + step;
      xr <= xr + 1'b1;
      busy <= xr != last;
    end
  end
  assign valid = busy;
  assign x = xr;
  assign value = acc;
  ps_level #(.I(I), .F(F)) out0 (.v(acc), .level(level));
endmodule
