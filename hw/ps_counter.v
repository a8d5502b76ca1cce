// The counter-directional unit (docs/hardware.md): two code interpolators from the span's ends toward
// each other, lane 0 from S stepping +dI (left to right), lane 1 from E stepping -dI (right to left),
// each with its row interpolator (x up, x down). On an odd span the left lane takes the middle pixel
// while the right one is blocked. Two pixels per clock after the load clock.
/* verilator lint_off UNUSEDSIGNAL */
module ps_counter #(
  parameter I = 12,
  parameter F = 12,
  parameter LEN = 13
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
  output wire [1:0]       valid,
  output wire [2*LEN-1:0] x,
  output wire [2*(I+F)-1:0] value,
  output wire [15:0]      level
);
  localparam W = I + F;
  reg [W-1:0] left, right, step;
  reg [LEN-1:0] xa, xb;  // the left and right lanes' pixels; xa <= xb while busy
  reg busy;
  wire both = xa != xb;  // the right lane has a pixel of its own this clock
  assign ready = !busy && !rst;  // in reset `load` is ignored: never offer to take it
  always @(posedge clk) begin
    if (rst) begin
      busy <= 1'b0;
    end else if (load && ready) begin
      left <= s_in;
      right <= e_in;
      step <= step_in;
      xa <= {LEN{1'b0}};
      xb <= length_in - 1'b1;
      busy <= 1'b1;
    end else if (busy) begin
      left <= left + step;
      xa <= xa + 1'b1;
      if (both) begin
        right <= right - step;
        xb <= xb - 1'b1;
      end
      busy <= xb - xa > 1;  // next clock's xa <= xb
    end
  end
  assign valid = {busy && both, busy};
  assign x = {xb, xa};
  assign value = {right, left};
  ps_level #(.I(I), .F(F)) out0 (.v(left), .level(level[7:0]));
  ps_level #(.I(I), .F(F)) out1 (.v(right), .level(level[15:8]));
endmodule
