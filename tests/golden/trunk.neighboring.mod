MODULE TrunkWeld
    ! generator: gen-rapid 0.1.0
    ! cell: trunk.yaml
    ! planner: neighboring
    ! grid (deg): 1.000
    ! clearance (mm): 10.0
    ! base: [0.0, -850.0, 0.0] yaw: 90.000
    ! moves: 21
    ! min clearance (mm): 11.0
    ! estimated time (s): 5.49

    CONST jointtarget A := [[90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[68.000,-22.000,-22.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[63.000,-17.000,-27.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_03 := [[28.000,18.000,8.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget B := [[30.000,20.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_01 := [[28.000,18.000,8.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via02_02 := [[27.000,17.000,8.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget C := [[25.000,15.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_01 := [[0.000,-10.000,-15.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget D := [[-25.000,15.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_01 := [[-27.000,17.000,8.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via04_02 := [[-28.000,18.000,8.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget E := [[-30.000,20.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_01 := [[-38.000,12.000,2.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_02 := [[-38.000,11.000,1.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_03 := [[-39.000,10.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_04 := [[-39.000,8.000,-2.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_05 := [[-40.000,7.000,-3.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_06 := [[-40.000,6.000,-4.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_07 := [[-63.000,-17.000,-27.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_08 := [[-68.000,-22.000,-22.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget F := [[-90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ A\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_03\NoEOffs, v300, fine, tool0;
        MoveAbsJ B\NoEOffs, v300, fine, tool0;
        MoveAbsJ via02_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via02_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ C\NoEOffs, v300, fine, tool0;
        MoveAbsJ via03_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ D\NoEOffs, v300, fine, tool0;
        MoveAbsJ via04_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via04_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ E\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_03\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_04\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_05\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_06\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_07\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_08\NoEOffs, v300, fine, tool0;
        MoveAbsJ F\NoEOffs, v300, fine, tool0;
    ENDPROC
ENDMODULE
