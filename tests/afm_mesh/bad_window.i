# expect: 39: inside the 500 nm x 500 nm map
# bad_window.i -- the window leaves the map: exit 2 naming the afm surface block
#
# Check:  build/bin/tribex check tests/afm_mesh/afm_track.i
# The substrate is a 20 nm x 30 nm window of di-1.di (500 nm scan, flattened Height channel 0) with a
# 10 nm wide contact track at 0.5 nm, graded away from it and with depth to a flat bottom 20 nm under the
# mean height, under a 2 nm bonded coating. The map is one of the sample files in inputs/data/afm.
begin sierra afm_track
  begin function ramp
    type = piecewise linear
    abscissa unit = ps
    begin values
      0 0
      1 1
    end values
  end function ramp

  begin property specification for material polysilicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 164 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material polysilicon

  begin property specification for material coating_film
    density = 2200 kg/m^3
    begin parameters for model elastic
      youngs modulus = 70 GPa
      poissons ratio = 0.17
    end parameters for model elastic
  end property specification for material coating_film

  begin solid section hex8
    formulation = mean_quadrature
  end solid section hex8

  begin finite element model substrate
    begin afm surface
      file = ../../inputs/data/afm/di-1.di
      channel = 0
      window = 490 200 20 30 nm
      track = 205 200 10 30 nm
      element size = 0.5 nm
      depth = 20 nm
      coating thickness = 2 nm
      coating layers = 4
      grading ratio = 1.3
    end afm surface
    begin parameters for block substrate
      material = polysilicon
      section = hex8
    end parameters for block substrate
    begin parameters for block coating
      material = coating_film
      section = hex8
    end parameters for block coating
  end finite element model substrate

  begin presto procedure press
    begin time control
      termination time = 1 ps
    end time control
    begin presto region track
      use finite element model substrate
      begin pressure
        side set = substrate_track
        function = ramp
        scale factor = 100 MPa
      end pressure
      begin silent boundary
        side set = substrate_bottom
      end silent boundary
      begin silent boundary
        side set = substrate_sides
      end silent boundary
    end presto region track
  end presto procedure press
end sierra afm_track
