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
    ! zoned vias: 0 of 5 (via zone fine)
    ! the paper's method alone: 24 moves, 33.12 s

    PERS tooldata tVacuum := [TRUE,[[0.000,0.000,250.000],[1.000000000,0.000000000,0.000000000,0.000000000]],[35.000,[0.000,0.000,150.000],[1,0,0,0],0,0,0]];

    CONST jointtarget home := [[0.000,0.000,0.000,0.000,60.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget above_pick1 := [[-51.340,37.495,-53.045,0.000,105.549,128.660],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget above_pick1_rt := [[1000.000,-1250.000,1250.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget pick1 := [[-51.340,30.141,-23.434,0.000,83.293,128.660],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pick1_rt := [[1000.000,-1250.000,950.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget lift1 := [[-51.340,37.495,-53.045,0.000,105.549,128.660],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget lift1_rt := [[1000.000,-1250.000,1250.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_01 := [[22.000,14.000,-1.000,0.000,85.433,145.180],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget above_place1 := [[61.557,13.789,-1.457,0.000,77.668,151.557],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget above_place1_rt := [[650.000,1200.000,950.000],[0.000000000,0.707106781,0.707106781,0.000000000],[0,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget place1 := [[61.557,17.299,12.131,0.000,60.570,151.557],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget place1_rt := [[650.000,1200.000,650.000],[0.000000000,0.707106781,0.707106781,0.000000000],[0,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget leave1 := [[61.557,13.789,-1.457,0.000,77.668,151.557],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget leave1_rt := [[650.000,1200.000,950.000],[0.000000000,0.707106781,0.707106781,0.000000000],[0,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via07_01 := [[-37.886,25.983,-41.309,0.000,101.364,132.097],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget above_pick2 := [[-51.340,37.495,-53.045,0.000,105.549,128.660],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget above_pick2_rt := [[1000.000,-1250.000,1250.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget pick2 := [[-51.340,30.141,-23.434,0.000,83.293,128.660],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pick2_rt := [[1000.000,-1250.000,950.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget lift2 := [[-51.340,37.495,-53.045,0.000,105.549,128.660],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget lift2_rt := [[1000.000,-1250.000,1250.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via10_01 := [[5.051,25.222,-52.899,0.000,97.910,142.229],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget above_place2 := [[67.891,40.907,-40.001,0.000,89.094,157.891],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget above_place2_rt := [[650.000,1600.000,950.000],[0.000000000,0.707106781,0.707106781,0.000000000],[0,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget place2 := [[67.891,40.679,-21.949,0.000,71.270,157.891],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget place2_rt := [[650.000,1600.000,650.000],[0.000000000,0.707106781,0.707106781,0.000000000],[0,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget leave2 := [[67.891,40.907,-40.001,0.000,89.094,157.891],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget leave2_rt := [[650.000,1600.000,950.000],[0.000000000,0.707106781,0.707106781,0.000000000],[0,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via13_01 := [[-3.242,27.754,-61.983,0.000,99.166,139.999],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget above_pick3 := [[-51.340,37.495,-53.045,0.000,105.549,128.660],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget above_pick3_rt := [[1000.000,-1250.000,1250.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget pick3 := [[-51.340,30.141,-23.434,0.000,83.293,128.660],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pick3_rt := [[1000.000,-1250.000,950.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget lift3 := [[-51.340,37.495,-53.045,0.000,105.549,128.660],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget lift3_rt := [[1000.000,-1250.000,1250.000],[0.000000000,1.000000000,0.000000000,0.000000000],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via16_01 := [[8.000,25.000,-24.000,0.000,95.722,190.400],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget above_place3 := [[54.462,40.271,-38.979,0.000,88.708,234.462],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget above_place3_rt := [[1000.000,1400.000,950.000],[0.000000000,1.000000000,0.000000000,0.000000000],[0,0,2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget place3 := [[54.462,40.195,-21.172,0.000,70.977,234.462],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget place3_rt := [[1000.000,1400.000,650.000],[0.000000000,1.000000000,0.000000000,0.000000000],[0,0,2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget leave3 := [[54.462,40.271,-38.979,0.000,88.708,234.462],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget leave3_rt := [[1000.000,1400.000,950.000],[0.000000000,1.000000000,0.000000000,0.000000000],[0,0,2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget home2 := [[0.000,0.000,0.000,0.000,60.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ home\NoEOffs, v1000, fine, tVacuum;
        MoveAbsJ above_pick1\NoEOffs, v1000, fine, tVacuum;
        MoveAbsJ pick1\NoEOffs, v200, fine, tVacuum;
        MoveAbsJ lift1\NoEOffs, v500, fine, tVacuum;
        MoveAbsJ via04_01\NoEOffs, v1000, fine, tVacuum;
        MoveAbsJ above_place1\NoEOffs, v1000, fine, tVacuum;
        MoveAbsJ place1\NoEOffs, v200, fine, tVacuum;
        MoveAbsJ leave1\NoEOffs, v500, fine, tVacuum;
        MoveAbsJ via07_01\NoEOffs, v1000, fine, tVacuum;
        MoveAbsJ above_pick2\NoEOffs, v1000, fine, tVacuum;
        MoveAbsJ pick2\NoEOffs, v200, fine, tVacuum;
        MoveAbsJ lift2\NoEOffs, v500, fine, tVacuum;
        MoveAbsJ via10_01\NoEOffs, v1000, fine, tVacuum;
        MoveAbsJ above_place2\NoEOffs, v1000, fine, tVacuum;
        MoveAbsJ place2\NoEOffs, v200, fine, tVacuum;
        MoveAbsJ leave2\NoEOffs, v500, fine, tVacuum;
        MoveAbsJ via13_01\NoEOffs, v1000, fine, tVacuum;
        MoveAbsJ above_pick3\NoEOffs, v1000, fine, tVacuum;
        MoveAbsJ pick3\NoEOffs, v200, fine, tVacuum;
        MoveAbsJ lift3\NoEOffs, v500, fine, tVacuum;
        MoveAbsJ via16_01\NoEOffs, v1000, fine, tVacuum;
        MoveAbsJ above_place3\NoEOffs, v1000, fine, tVacuum;
        MoveAbsJ place3\NoEOffs, v200, fine, tVacuum;
        MoveAbsJ leave3\NoEOffs, v500, fine, tVacuum;
        MoveAbsJ home2\NoEOffs, v1000, fine, tVacuum;
    ENDPROC
ENDMODULE
