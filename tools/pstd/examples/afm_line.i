# afm_line.i -- the PSTD model (seed report 2.1.9) on a line of a real AFM map, with the apparent-area study.
#
#   run:  tribex pstd tools/pstd/examples/afm_line.i             (from the repository root)
#         tribex pstd tools/pstd/examples/afm_line.i --copies 2  (options after the deck override it)
#
#   substrate: row 30 of matrix-3.txt (10 um, 256 px, levelled), periodic
#   counterface: 3 x 2 um pieces of seeded columns, each put into point contact, linked end to end
#       ---------  ---------  ---------      counterface (rigid), moves +x, device x decreases to 0
#   ~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~  substrate line
#
# Exercises: the AFM reader, the 2-D line-contact law, stepping, PSTD detection, the study, all outputs.
begin pstd
  afm             = ../../../../shared/data/afm/matrix-3.txt   # relative to this deck's folder
  line            = 30
  segments        = 3
  segment length  = 2 um
  law             = 2d
  youngs modulus  = 161 GPa
  poissons ratio  = 0.23
  depth           = 50 um
  shear strength  = 195 MPa
  normal force    = 2.2 mN
  restoring       = 0.5796,4.3572,0.1080,0.0435,-0.0001
  copies          = 4
  study           = yes
  output          = afm_line_output
end pstd
