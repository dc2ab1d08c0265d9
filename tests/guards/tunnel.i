# Issue 29 item 6: a sphere thrown at the flat at 1e5 m/s moves several capture distances per step and
# would pass through it unseen. The run must stop (contact motion limit, exit 3) naming tunnelling,
# with the contact_motion warning in summary.json and valid outputs. Before the guard: exit 0.
begin sierra tunnel
  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon
  begin solid section hex8
    formulation = fully_integrated
  end solid section hex8
  begin finite element model asperity
    begin generated asperity
      radius = 10 nm
      tip width = 12 nm
      tip height = 10 nm
      substrate width = 24 nm
      substrate depth = 8 nm
      element size = 2 nm
      gap = 2 nm
    end generated asperity
    begin parameters for block tip
      material = silicon
      section = hex8
    end parameters for block tip
    begin parameters for block substrate
      material = silicon
      section = hex8
    end parameters for block substrate
  end finite element model asperity
  begin presto procedure throw
    begin time control
      termination time = 2 ps
    end time control
    begin presto region main
      use finite element model asperity
      begin fixed displacement
        node set = substrate_bottom
        components = x y z
      end fixed displacement
      begin initial velocity
        block = tip
        velocity = 0 0 -1e5 m/s
      end initial velocity
      begin contact definition tip_on_flat
        contact surface tip contains tip_surface
        contact surface flat contains substrate_top
        begin interaction sphere_flat
          surfaces = tip flat
          model = frictionless
        end interaction sphere_flat
      end contact definition tip_on_flat
      begin history output hist
        step increment = 1
      end history output hist
    end presto region main
  end presto procedure throw
end sierra tunnel
