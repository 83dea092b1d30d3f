MODULE Irb1200Auto
    ! generator: gen-rapid 0.1.0
    ! cell: irb1200_base_auto.yaml
    ! model: irb1200_5_90 (ABB IRB 1200-5/0.90, built into gen-rapid)
    ! urdf: irb1200_5_90.urdf
    ! controller: irb1200_5_90.controller.yaml
    ! coupling: serial (axes 1..6 = URDF joints 1..6)
    ! planner: extensile
    ! grid (deg): 2.000
    ! clearance (mm): 10.0
    ! base: [115.0, 45.0, 0.0] yaw: 0.000
    ! moves: 2
    ! min clearance (mm): 104.4
    ! estimated time (s): 4.66
    ! cycle: open: the routine ends at P3, not where it starts (P1); motion.cycle: true closes it
    ! zoned vias: 0 of 0 (via zone fine)

    CONST jointtarget P1 := [[-42.537,28.645,-11.571,0.000,60.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget P2 := [[31.251,33.629,-12.668,0.000,60.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget P3 := [[58.761,-11.838,9.237,0.000,60.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ P1\NoEOffs, v300, fine, tool0;
        MoveAbsJ P2\NoEOffs, v300, fine, tool0;
        MoveAbsJ P3\NoEOffs, v300, fine, tool0;
    ENDPROC
ENDMODULE
