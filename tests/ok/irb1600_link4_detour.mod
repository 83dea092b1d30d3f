MODULE Irb1600Link4
    ! generator: gen-rapid 0.1.0
    ! cell: irb1600_link4_detour.yaml
    ! model: irb1600_8_145 (ABB IRB 1600-8/1.45, built into gen-rapid)
    ! urdf: irb1600_8_145.urdf
    ! controller: irb1600_8_145.controller.yaml
    ! coupling: serial (axes 1..6 = URDF joints 1..6)
    ! planner: extensile
    ! grid (deg): 2.000
    ! clearance (mm): 10.0
    ! base: [0.0, 0.0, 0.0] yaw: 0.000
    ! moves: 2
    ! min clearance (mm): 12.3
    ! estimated time (s): 6.21
    ! cycle: open: the routine ends at P2, not where it starts (P1); motion.cycle: true closes it
    ! zoned vias: 0 of 1 (via zone fine)
    ! the paper's method alone: 2 moves, 6.47 s

    CONST jointtarget P1 := [[-50.000,20.000,-20.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[4.406,6.781,-31.750,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget P2 := [[50.000,20.000,-20.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ P1\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ P2\NoEOffs, v300, fine, tool0;
    ENDPROC
ENDMODULE
