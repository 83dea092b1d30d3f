MODULE Diag
    ! generator: gen-rapid 0.1.0
    ! cell: no_obstacles_depth_first.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: depth-first
    ! grid (deg): 10.000
    ! clearance (mm): 10.0
    ! base: [0.0, 0.0, 0.0] yaw: 0.000
    ! moves: 1
    ! min clearance (mm): none (no obstacles)
    ! estimated time (s): 0.74
    ! cycle: open: the routine ends at Q, not where it starts (P); motion.cycle: true closes it
    ! zoned vias: 0 of 0 (via zone fine)

    CONST jointtarget P := [[0.000,0.000,0.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget Q := [[10.000,10.000,0.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ P\NoEOffs, v300, fine, tool0;
        MoveAbsJ Q\NoEOffs, v300, fine, tool0;
    ENDPROC
ENDMODULE
