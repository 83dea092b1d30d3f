MODULE CompleteSearch
    ! generator: gen-rapid 0.1.0
    ! cell: complete_search_2deg.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: extensile
    ! grid (deg): 2.000
    ! clearance (mm): 25.0
    ! base: [0.0, 0.0, 0.0] yaw: 0.000
    ! moves: 3
    ! min clearance (mm): 25.2
    ! estimated time (s): 12.79
    ! cycle: open: the routine ends at Q, not where it starts (P); motion.cycle: true closes it
    ! zoned vias: 0 of 2 (via zone fine)
    ! the paper's method alone: 3 moves, 12.91 s

    CONST jointtarget P := [[-34.000,34.000,36.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[96.281,-54.250,-40.438,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[120.000,-34.000,-20.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget Q := [[120.000,30.000,40.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ P\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ Q\NoEOffs, v300, fine, tool0;
    ENDPROC
ENDMODULE
