MODULE ShelfLoad
    ! generator: gen-rapid 0.1.0
    ! cell: shelf.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: extensile
    ! grid (deg): 1.000
    ! clearance (mm): 15.0
    ! base: [0.0, 0.0, 0.0] yaw: 0.000
    ! moves: 33
    ! min clearance (mm): 15.0
    ! estimated time (s): 18.63
    ! cycle: closed: the routine ends where it starts; its time is a cycle time
    ! zoned vias: 0 of 28 (via zone fine)
    ! the paper's method alone: 46 moves, 20.58 s

    CONST jointtarget home := [[0.000,-20.000,20.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[-5.898,-19.492,24.102,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[-11.000,-15.000,29.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_03 := [[-37.078,22.109,29.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_04 := [[-35.003,40.692,28.688,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_05 := [[-32.953,52.013,20.959,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_06 := [[-28.325,59.571,10.073,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget lower_right := [[-25.000,65.000,0.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_01 := [[-27.688,58.719,12.031,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_02 := [[-33.000,52.000,21.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_03 := [[-35.273,41.563,27.672,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_04 := [[-42.154,24.218,28.489,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_05 := [[-51.945,12.196,16.981,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_06 := [[-44.000,2.000,5.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_07 := [[-34.055,11.891,-4.453,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget upper_right := [[-25.000,20.000,-5.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_01 := [[-13.000,-13.000,-5.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_02 := [[0.047,-25.547,-17.594,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_03 := [[16.000,-10.000,-5.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget upper_left := [[25.000,20.000,-5.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_01 := [[39.000,5.000,1.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_02 := [[43.094,1.219,5.109,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_03 := [[53.000,11.000,16.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_04 := [[36.000,29.000,34.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_05 := [[33.000,48.000,25.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_06 := [[30.375,54.953,18.047,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget lower_left := [[25.000,65.000,0.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_01 := [[27.688,58.719,12.031,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_02 := [[33.000,52.000,21.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_03 := [[34.781,41.781,27.891,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_04 := [[32.093,26.059,32.831,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_05 := [[10.595,-14.623,29.840,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_06 := [[3.395,-22.022,23.330,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget home_again := [[0.000,-20.000,20.000,0.000,0.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ home\NoEOffs, v500, fine, tool0;
        MoveAbsJ via01_01\NoEOffs, v500, fine, tool0;
        MoveAbsJ via01_02\NoEOffs, v500, fine, tool0;
        MoveAbsJ via01_03\NoEOffs, v500, fine, tool0;
        MoveAbsJ via01_04\NoEOffs, v500, fine, tool0;
        MoveAbsJ via01_05\NoEOffs, v500, fine, tool0;
        MoveAbsJ via01_06\NoEOffs, v500, fine, tool0;
        MoveAbsJ lower_right\NoEOffs, v500, fine, tool0;
        MoveAbsJ via02_01\NoEOffs, v500, fine, tool0;
        MoveAbsJ via02_02\NoEOffs, v500, fine, tool0;
        MoveAbsJ via02_03\NoEOffs, v500, fine, tool0;
        MoveAbsJ via02_04\NoEOffs, v500, fine, tool0;
        MoveAbsJ via02_05\NoEOffs, v500, fine, tool0;
        MoveAbsJ via02_06\NoEOffs, v500, fine, tool0;
        MoveAbsJ via02_07\NoEOffs, v500, fine, tool0;
        MoveAbsJ upper_right\NoEOffs, v500, fine, tool0;
        MoveAbsJ via03_01\NoEOffs, v500, fine, tool0;
        MoveAbsJ via03_02\NoEOffs, v500, fine, tool0;
        MoveAbsJ via03_03\NoEOffs, v500, fine, tool0;
        MoveAbsJ upper_left\NoEOffs, v500, fine, tool0;
        MoveAbsJ via04_01\NoEOffs, v500, fine, tool0;
        MoveAbsJ via04_02\NoEOffs, v500, fine, tool0;
        MoveAbsJ via04_03\NoEOffs, v500, fine, tool0;
        MoveAbsJ via04_04\NoEOffs, v500, fine, tool0;
        MoveAbsJ via04_05\NoEOffs, v500, fine, tool0;
        MoveAbsJ via04_06\NoEOffs, v500, fine, tool0;
        MoveAbsJ lower_left\NoEOffs, v500, fine, tool0;
        MoveAbsJ via05_01\NoEOffs, v500, fine, tool0;
        MoveAbsJ via05_02\NoEOffs, v500, fine, tool0;
        MoveAbsJ via05_03\NoEOffs, v500, fine, tool0;
        MoveAbsJ via05_04\NoEOffs, v500, fine, tool0;
        MoveAbsJ via05_05\NoEOffs, v500, fine, tool0;
        MoveAbsJ via05_06\NoEOffs, v500, fine, tool0;
        MoveAbsJ home_again\NoEOffs, v500, fine, tool0;
    ENDPROC
ENDMODULE
