MODULE Auto1
    ! generator: gen-rapid 0.1.0
    ! cell: base_auto_in_range.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: extensile
    ! grid (deg): 5.000
    ! clearance (mm): 10.0
    ! base: [585.0, 425.0, 0.0] yaw: 45.000
    ! moves: 2
    ! min clearance (mm): none (no obstacles)
    ! estimated time (s): 9.54
    ! cycle: open: the routine ends at P3, not where it starts (P1); motion.cycle: true closes it
    ! zoned vias: 0 of 0 (via zone fine)

    CONST jointtarget P1 := [[-91.302,-65.674,-4.639,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget P2 := [[41.878,-60.877,-17.679,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget P3 := [[-111.516,1.350,40.361,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ P1\NoEOffs, v300, fine, tool0;
        MoveAbsJ P2\NoEOffs, v300, fine, tool0;
        MoveAbsJ P3\NoEOffs, v300, fine, tool0;
    ENDPROC
ENDMODULE
