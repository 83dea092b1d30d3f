MODULE PalletStack
    ! generator: gen-rapid 0.1.0
    ! cell: pallet-stack.yaml
    ! model: irb4600_60_205 (ABB IRB 4600-60/2.05, built into gen-rapid)
    ! urdf: irb4600_60_205.urdf
    ! controller: irb4600_60_205.controller.yaml
    ! coupling: serial (axes 1..6 = URDF joints 1..6)
    ! planner: extensile
    ! grid (deg): 1.000
    ! clearance (mm): 20.0
    ! base: [0.0, 0.0, 0.0] yaw: 0.000
    ! tool: tVacuum (declared below; collision shapes: adapter, beam_frame, cup_plate)
    ! wobj: wobj0 (robtargets are in the world frame)
    ! frames: robtargets and the user frame are given in the cell frame; they mean the cell's poses only if the controller's base frame is the base and yaw above
    ! moves: 24
    ! min clearance (mm): 20.0
    ! estimated time (s): 33.11
    ! cycle: closed: the routine ends where it starts; its time is a cycle time
    ! zoned vias: 0 of 5 (via zone fine)

    PERS tooldata tVacuum := [TRUE,[[0.000,0.000,250.000],[1.000000000,0.000000000,0.000000000,0.000000000]],[35.000,[0.000,0.000,150.000],[1,0,0,0],0,0,0]];

    CONST jointtarget home := [[0.000,0.000,0.000,0.000,60.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget above_pick1_rt := [[1000.000,-1250.000,1250.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pick1_rt := [[1000.000,-1250.000,950.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget lift1_rt := [[1000.000,-1250.000,1250.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_01 := [[22.000,14.000,-1.000,0.000,85.433,145.180],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget above_place1_rt := [[650.000,1200.000,950.000],[0.000000000,0.707106781,0.707106781,0.000000000],[0,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget place1_rt := [[650.000,1200.000,650.000],[0.000000000,0.707106781,0.707106781,0.000000000],[0,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget leave1_rt := [[650.000,1200.000,950.000],[0.000000000,0.707106781,0.707106781,0.000000000],[0,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via07_01 := [[-37.886,25.983,-41.309,0.000,101.364,132.097],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget above_pick2_rt := [[1000.000,-1250.000,1250.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pick2_rt := [[1000.000,-1250.000,950.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget lift2_rt := [[1000.000,-1250.000,1250.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via10_01 := [[5.051,25.222,-52.899,0.000,97.911,142.229],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget above_place2_rt := [[650.000,1600.000,950.000],[0.000000000,0.707106781,0.707106781,0.000000000],[0,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget place2_rt := [[650.000,1600.000,650.000],[0.000000000,0.707106781,0.707106781,0.000000000],[0,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget leave2_rt := [[650.000,1600.000,950.000],[0.000000000,0.707106781,0.707106781,0.000000000],[0,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via13_01 := [[-3.242,27.754,-61.983,0.000,99.166,139.999],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget above_pick3_rt := [[1000.000,-1250.000,1250.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pick3_rt := [[1000.000,-1250.000,950.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget lift3_rt := [[1000.000,-1250.000,1250.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via16_01 := [[8.000,25.000,-24.000,0.000,95.721,190.400],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget above_place3_rt := [[1000.000,1400.000,950.000],[0.000000000,1.000000000,0.000000000,0.000000000],[0,0,2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget place3_rt := [[1000.000,1400.000,650.000],[0.000000000,1.000000000,0.000000000,0.000000000],[0,0,2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget leave3_rt := [[1000.000,1400.000,950.000],[0.000000000,1.000000000,0.000000000,0.000000000],[0,0,2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget home2 := [[0.000,0.000,0.000,0.000,60.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        ConfJ \On;
        ConfL \On;
        MoveAbsJ home\NoEOffs, v1000, fine, tVacuum;
        MoveJ above_pick1_rt, v1000, fine, tVacuum;
        MoveJ pick1_rt, v200, fine, tVacuum;
        MoveJ lift1_rt, v500, fine, tVacuum;
        MoveAbsJ via04_01\NoEOffs, v1000, fine, tVacuum;
        MoveJ above_place1_rt, v1000, fine, tVacuum;
        MoveJ place1_rt, v200, fine, tVacuum;
        MoveJ leave1_rt, v500, fine, tVacuum;
        MoveAbsJ via07_01\NoEOffs, v1000, fine, tVacuum;
        MoveJ above_pick2_rt, v1000, fine, tVacuum;
        MoveJ pick2_rt, v200, fine, tVacuum;
        MoveJ lift2_rt, v500, fine, tVacuum;
        MoveAbsJ via10_01\NoEOffs, v1000, fine, tVacuum;
        MoveJ above_place2_rt, v1000, fine, tVacuum;
        MoveJ place2_rt, v200, fine, tVacuum;
        MoveJ leave2_rt, v500, fine, tVacuum;
        MoveAbsJ via13_01\NoEOffs, v1000, fine, tVacuum;
        MoveJ above_pick3_rt, v1000, fine, tVacuum;
        MoveJ pick3_rt, v200, fine, tVacuum;
        MoveJ lift3_rt, v500, fine, tVacuum;
        MoveAbsJ via16_01\NoEOffs, v1000, fine, tVacuum;
        MoveJ above_place3_rt, v1000, fine, tVacuum;
        MoveJ place3_rt, v200, fine, tVacuum;
        MoveJ leave3_rt, v500, fine, tVacuum;
        MoveAbsJ home2\NoEOffs, v1000, fine, tVacuum;
    ENDPROC
ENDMODULE
