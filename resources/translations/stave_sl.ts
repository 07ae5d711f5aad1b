<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="sl" sourcelanguage="en">
<context>
    <name>AlarmDetailOverlay</name>
    <message>
        <location filename="../../app/screens/alarm_detail.py" line="+128"/>
        <source>What was found</source>
        <translation>Kaj je bilo ugotovljeno</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Source: %1</source>
        <translation>Vir: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Kind: %1</source>
        <translation>Vrsta: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Device reports: %1</source>
        <translation>Naprava sporoča: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Probable causes</source>
        <translation>Verjetni vzroki</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>What to do</source>
        <translation>Kaj storiti</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>History</source>
        <translation>Zgodovina</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Acknowledge</source>
        <translation>Potrdi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Close</source>
        <translation>Zapri</translation>
    </message>
</context>
<context>
    <name>AlarmStates</name>
    <message>
        <location filename="../../app/screens/texts.py" line="+70"/>
        <location line="+8"/>
        <source>normal</source>
        <translation>normalno</translation>
    </message>
    <message>
        <location line="-7"/>
        <location line="+8"/>
        <source>active, unacknowledged</source>
        <translation>aktiven, nepotrjen</translation>
    </message>
    <message>
        <location line="-7"/>
        <location line="+8"/>
        <source>active, acknowledged</source>
        <translation>aktiven, potrjen</translation>
    </message>
    <message>
        <location line="-7"/>
        <location line="+8"/>
        <source>cleared, unacknowledged</source>
        <translation>odpravljen, nepotrjen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>shelved</source>
        <translation>odložen</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>fault</source>
        <translation>napaka</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>warning</source>
        <translation>opozorilo</translation>
    </message>
</context>
<context>
    <name>AlarmText</name>
    <message>
        <location filename="catalogue_strings.py" line="+176"/>
        <source>A cable to the motor or its encoder is damaged.</source>
        <translation>Kabel do motorja ali njegovega dajalnika je poškodovan.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A device answered but refused what the machine asked of it.</source>
        <translation>Naprava se je odzvala, vendar je zavrnila, kar je stroj zahteval.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A device was replaced by another model or firmware.</source>
        <translation>Naprava je bila zamenjana z drugim modelom ali vdelano programsko opremo.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A drive did not switch its power stage on when asked.</source>
        <translation>Pogon na zahtevo ni vklopil močnostne stopnje.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A drive no longer knows where its axis is; the cut was stopped.</source>
        <translation>Pogon ne ve več, kje je njegova os; rezanje je bilo ustavljeno.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A drive or encoder problem.</source>
        <translation>Težava s pogonom ali dajalnikom.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A drive or the I/O module lost its supply or restarted.</source>
        <translation>Pogon ali V/I modul je izgubil napajanje ali se je ponovno zagnal.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A drive or the I/O refused a request</source>
        <translation>Pogon ali V/I je zavrnil zahtevo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A drive or the I/O reported an event; the machine keeps going.</source>
        <translation>Pogon ali V/I je sporočil dogodek; stroj dela naprej.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A drive switched its power stage off while the axis was meant to move.</source>
        <translation>Pogon je izklopil močnostno stopnjo, ko bi se os morala premikati.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A faulty or misadjusted sensor.</source>
        <translation>Okvarjen ali slabo nastavljen senzor.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A jog stopped because the screen no longer confirmed that its button is held.</source>
        <translation>Ročni premik se je ustavil, ker zaslon ni več potrjeval, da je gumb pritisnjen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A limit switch is faulty or was hit by a board.</source>
        <translation>Končno stikalo je okvarjeno ali ga je zadela deska.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A network or bus cable is unplugged or broken.</source>
        <translation>Omrežni kabel ali kabel vodila je izklopljen ali pretrgan.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A safety relay or a wire of the chain is open.</source>
        <translation>Varnostni rele ali vodnik verige je odprt.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A servo drive reports a fault and has switched its motor off.</source>
        <translation>Servopogon sporoča napako in je izklopil motor.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A software fault.</source>
        <translation>Napaka v programski opremi.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A switch between them failed.</source>
        <translation>Odpovedalo je stikalo med njimi.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A warning inside the device.</source>
        <translation>Opozorilo v napravi.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A wrong PIN was tried several times.</source>
        <translation>Večkrat je bil vnesen napačen PIN.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Air pressure too low.</source>
        <translation>Prenizek tlak zraka.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>An axis did not find its home position within the expected time.</source>
        <translation>Os v pričakovanem času ni našla referenčne lege.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>An axis lags too far behind where it should be; it was stopped before it could go somewhere unexpected.</source>
        <translation>Os preveč zaostaja za predpisano lego; ustavljena je bila, preden bi lahko zašla, kamor ne bi smela.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>An axis ran onto its end-of-travel switch and was stopped.</source>
        <translation>Os je zapeljala na končno stikalo in je bila ustavljena.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>An axis stands where the approach cannot go round the board.</source>
        <translation>Os stoji tam, kjer dovoz ne more okoli deske.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>An emergency stop button is pressed.</source>
        <translation>Pritisnjena je tipka za zasilno zaustavitev.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>An encoder signal was lost.</source>
        <translation>Izgubljen je bil signal dajalnika.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Another program holds the database.</source>
        <translation>Drug program zaseda podatkovno bazo.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Axis lost its home position</source>
        <translation>Os je izgubila referenčno lego</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Board removed during the cycle</source>
        <translation>Deska odstranjena med ciklom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Board too narrow to close the barrel</source>
        <translation>Deska je preozka za zaprtje soda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Call a technician to free disk space or the database; the records are written once it answers.</source>
        <translation>Pokličite tehnika, da sprosti prostor na disku ali podatkovno bazo; zapisi se zapišejo, ko se baza odzove.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Call a technician with the code in the details; then press Reset.</source>
        <translation>Pokličite tehnika in mu povejte kodo iz podrobnosti; nato pritisnite Ponastavi.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Centering device did not reach its sensor</source>
        <translation>Centrirna naprava ni dosegla senzorja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Check the air pressure and the centering device, then press Reset.</source>
        <translation>Preverite tlak zraka in centrirno napravo, nato pritisnite Ponastavi.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Check the air pressure and the clamps, then press Reset.</source>
        <translation>Preverite tlak zraka in vpenjala, nato pritisnite Ponastavi.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Check the axis and its home switch, then press Reset and home again.</source>
        <translation>Preverite os in njeno referenčno stikalo, nato pritisnite Ponastavi in ponovno referencirajte.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Check the cables and the supply of the device named in the details, then press Reset (it reconnects).</source>
        <translation>Preverite kable in napajanje naprave, navedene v podrobnostih, nato pritisnite Ponastavi (ponovno se poveže).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Check the cutter and the motor protection. Press Reset, then resume or abandon the board.</source>
        <translation>Preverite rezkar in motorsko zaščito. Pritisnite Ponastavi, nato desko nadaljujte ali opustite.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Check the drive&apos;s display and its supply, then press Reset.</source>
        <translation>Preverite prikaz na pogonu in njegovo napajanje, nato pritisnite Ponastavi.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Check the emergency stop buttons and the drive&apos;s display, then press Reset.</source>
        <translation>Preverite tipke za zasilno zaustavitev in prikaz na pogonu, nato pritisnite Ponastavi.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Check the gauge and its cable, then press Reset: the board is measured again.</source>
        <translation>Preverite merilnik in njegov kabel, nato pritisnite Ponastavi: deska bo ponovno izmerjena.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Check the gauge&apos;s display and cable, then press Reset.</source>
        <translation>Preverite prikaz na merilniku in kabel, nato pritisnite Ponastavi.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Check the handwheel&apos;s cable and plug, then press Reset. If it repeats, call a technician.</source>
        <translation>Preverite kabel in vtič ročnega kolesa, nato pritisnite Ponastavi. Če se ponovi, pokličite tehnika.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Check the spindle&apos;s motor protection switch, then press Reset.</source>
        <translation>Preverite motorsko zaščitno stikalo vretena, nato pritisnite Ponastavi.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Clamps did not reach their sensor</source>
        <translation>Vpenjala niso dosegla senzorja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear the axis, check that it moves freely, then press Reset. If it repeats, lower the feed or call a technician.</source>
        <translation>Sprostite os, preverite, da se prosto giblje, nato pritisnite Ponastavi. Če se ponovi, zmanjšajte podajanje ali pokličite tehnika.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Close the guard, check that nothing is in the way, then press Reset.</source>
        <translation>Zaprite zaščito, preverite, da nič ne ovira, nato pritisnite Ponastavi.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Communication with the drives or I/O lost</source>
        <translation>Izgubljena komunikacija s pogoni ali V/I</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cut to fit, this board would leave a gap in the barrel that no stave can close.</source>
        <translation>Če bi to desko odrezali, bi v sodu ostala reža, ki je ne more zapreti nobena doga.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Device event</source>
        <translation>Dogodek naprave</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drive did not enable</source>
        <translation>Pogon se ni vklopil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drive fault</source>
        <translation>Napaka pogona</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drive not enabled during motion</source>
        <translation>Pogon med gibanjem ni vklopljen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Electrical noise on the handwheel&apos;s cable or a bad connector.</source>
        <translation>Električne motnje na kablu ročnega kolesa ali slab konektor.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Emergency stop</source>
        <translation>Zasilna zaustavitev</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Feed or acceleration set higher than the axis can follow.</source>
        <translation>Podajanje ali pospešek je nastavljen višje, kot mu os lahko sledi.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Following error too large</source>
        <translation>Prevelik pogrešek sledenja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Guard open during motion</source>
        <translation>Zaščita odprta med gibanjem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Handwheel count jumped further than a hand can turn it</source>
        <translation>Števec ročnega kolesa je skočil dlje, kot ga lahko zavrti roka</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Homing did not complete</source>
        <translation>Referenciranje ni končano</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Internal error in the machine process</source>
        <translation>Notranja napaka v procesu stroja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jog stopped: no refresh from the screen</source>
        <translation>Ročni premik ustavljen: zaslon ni osvežil ukaza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit switch reached</source>
        <translation>Doseženo končno stikalo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Make sure nobody is in danger, release the button (turn it), then press Reset.</source>
        <translation>Prepričajte se, da nihče ni v nevarnosti, sprostite tipko (zavrtite jo), nato pritisnite Ponastavi.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Make sure the table is clear or the board is in place, then press Reset.</source>
        <translation>Prepričajte se, da je miza prosta ali da je deska na svojem mestu, nato pritisnite Ponastavi.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Measured width not allowed for this recipe</source>
        <translation>Izmerjena širina ni dovoljena za ta recept</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move refused: it would cross the board</source>
        <translation>Premik zavrnjen: šel bi čez desko</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Note the time and the details, press Reset, and tell service.</source>
        <translation>Zapišite si čas in podrobnosti, pritisnite Ponastavi in obvestite servis.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Over-current or over-temperature: the axis is stuck or overloaded.</source>
        <translation>Prevelik tok ali previsoka temperatura: os je zagozdena ali preobremenjena.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>PIN entry locked after repeated wrong PINs</source>
        <translation>Vnos PIN zaklenjen po ponavljajočih se napačnih PIN-ih</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Plug the gauge in again, then press Reset (it reconnects).</source>
        <translation>Ponovno priklopite merilnik, nato pritisnite Ponastavi (ponovno se poveže).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Press Reset and home the machine before the next board.</source>
        <translation>Pritisnite Ponastavi in pred naslednjo desko referencirajte stroj.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Press Reset, jog the axis away from the switch on the Manual screen (the opposite direction only), then home the machine.</source>
        <translation>Pritisnite Ponastavi, na zaslonu Ročno premaknite os stran od stikala (samo v nasprotni smeri), nato referencirajte stroj.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Press Reset, move the cutter clear of the board on the Manual screen, then start again.</source>
        <translation>Pritisnite Ponastavi, na zaslonu Ročno umaknite rezkar od deske, nato ponovno zaženite.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Press and hold the jog button again.</source>
        <translation>Ponovno pritisnite in držite gumb za ročni premik.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Production and alarm records are kept on the side because the database is busy or missing; nothing is lost yet.</source>
        <translation>Zapisi o proizvodnji in alarmih se hranijo ob strani, ker je podatkovna baza zasedena ali je ni; nič še ni izgubljeno.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Read the details; call a technician if it repeats.</source>
        <translation>Preberite podrobnosti; če se ponavlja, pokličite tehnika.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read the fault code in the details, look at the axis for anything jammed, then press Reset. If it comes back, call a technician with the code.</source>
        <translation>Preberite kodo napake v podrobnostih, preverite, ali se je os kje zagozdila, nato pritisnite Ponastavi. Če se napaka vrne, pokličite tehnika in mu povejte kodo.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Records waiting for the database</source>
        <translation>Zapisi čakajo na podatkovno bazo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Somebody opened the guard.</source>
        <translation>Nekdo je odprl zaščito.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spindle did not start</source>
        <translation>Vreteno se ni zagnalo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spindle stopped while cutting</source>
        <translation>Vreteno se je ustavilo med rezanjem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Supply voltage too high or too low.</source>
        <translation>Napajalna napetost je previsoka ali prenizka.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Take the board off (or choose the right recipe), then press Reset.</source>
        <translation>Odstranite desko (ali izberite pravi recept), nato pritisnite Ponastavi.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Take the board off and check the recipe, then press Reset.</source>
        <translation>Odstranite desko in preverite recept, nato pritisnite Ponastavi.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Take the board off and check the recipe, then press Reset. If it repeats with a good recipe, call service with the details.</source>
        <translation>Odstranite desko in preverite recept, nato pritisnite Ponastavi. Če se ponovi z dobrim receptom, pokličite servis in mu povejte podrobnosti.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Take the board off and put a wider one on, then press Reset.</source>
        <translation>Odstranite desko in položite širšo, nato pritisnite Ponastavi.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The axis is blocked or runs stiffly (chips, a board in the way, dry guides).</source>
        <translation>Os je blokirana ali teče težko (ostružki, deska na poti, suha vodila).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The axis was blocked or stopped during homing.</source>
        <translation>Os je bila med referenciranjem blokirana ali ustavljena.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The axis was jogged past its range.</source>
        <translation>Os je bila ročno premaknjena čez svoje območje.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The board is in the way or the clamps are jammed.</source>
        <translation>Deska je na poti ali pa so vpenjala zagozdena.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The board is in the way or the device is jammed.</source>
        <translation>Deska je na poti ali pa je naprava zagozdena.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The board is narrower or wider than the recipe can cut; it was not cut.</source>
        <translation>Deska je ožja ali širša, kot jo recept lahko odreže; ni bila odrezana.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The board is narrower than the barrel still needs.</source>
        <translation>Deska je ožja, kot jo sod še potrebuje.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The board is too narrow or too wide for this recipe.</source>
        <translation>Deska je preozka ali preširoka za ta recept.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The board is wider than the machine can cut.</source>
        <translation>Deska je širša, kot jo stroj lahko odreže.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The board was taken off or moved.</source>
        <translation>Deska je bila odstranjena ali premaknjena.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The centering device did not extend or retract in time.</source>
        <translation>Centrirna naprava se ni pravočasno iztegnila ali umaknila.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The clamps did not close or open in time, as their sensor reports.</source>
        <translation>Vpenjala se po poročilu senzorja niso pravočasno zaprla ali odprla.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The computer no longer hears a drive or the I/O; the machine stopped.</source>
        <translation>Računalnik ne sliši več pogona ali V/I; stroj se je ustavil.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The cut would need an axis beyond its travel; nothing moved there.</source>
        <translation>Rez bi zahteval os zunaj njenega hoda; tja se ni nič premaknilo.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The device is configured differently from the machine&apos;s configuration.</source>
        <translation>Naprava je nastavljena drugače, kot določa konfiguracija stroja.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The disk is full or slow.</source>
        <translation>Disk je poln ali počasen.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The drive is in fault or has no supply.</source>
        <translation>Pogon je v napaki ali nima napajanja.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The drive lost its supply.</source>
        <translation>Pogon je izgubil napajanje.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The drive was switched off or restarted.</source>
        <translation>Pogon je bil izklopljen ali ponovno zagnan.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The drive&apos;s enable or safe torque off input dropped.</source>
        <translation>Vhod za omogočitev ali varni izklop navora pogona je izpadel.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The emergency stop chain is open: every drive stopped and lost power.</source>
        <translation>Veriga zasilne zaustavitve je odprta: vsi pogoni so se ustavili in izgubili napajanje.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The emergency stop chain or safe torque off is still open.</source>
        <translation>Veriga zasilne zaustavitve ali varni izklop navora je še odprt.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The gauge is not in contact with the board.</source>
        <translation>Merilnik se ne dotika deske.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The gauge lost its supply.</source>
        <translation>Merilnik je izgubil napajanje.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The gauge reports its own error (out of range, no contact).</source>
        <translation>Merilnik sporoča lastno napako (zunaj območja, ni stika).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The gauge&apos;s cable is loose.</source>
        <translation>Kabel merilnika je razrahljan.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The gauge&apos;s cable or adapter is unplugged.</source>
        <translation>Kabel ali vmesnik merilnika je izklopljen.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The guard switch is loose or badly adjusted.</source>
        <translation>Stikalo zaščite je razrahljano ali slabo nastavljeno.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The guard was opened while an axis or the cutter moved; the machine stopped.</source>
        <translation>Zaščita je bila odprta, ko se je premikala os ali rezkar; stroj se je ustavil.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The handwheel or its counter input is faulty.</source>
        <translation>Ročno kolo ali njegov števni vhod je okvarjen.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The handwheel&apos;s counter changed by more between two readings than a hand can turn it; nothing moved on that reading.</source>
        <translation>Števec ročnega kolesa se je med dvema odčitkoma spremenil bolj, kot ga lahko zavrti roka; ob tem odčitku se ni nič premaknilo.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The home position is lost or wrong.</source>
        <translation>Referenčna lega je izgubljena ali napačna.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The home switch is faulty, dirty or out of place.</source>
        <translation>Referenčno stikalo je okvarjeno, umazano ali premaknjeno.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The machine could not compute the cut for this board.</source>
        <translation>Stroj za to desko ni mogel izračunati reza.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The machine&apos;s software met a situation it does not handle; it stopped safely.</source>
        <translation>Programska oprema stroja je naletela na stanje, ki ga ne obravnava; varno se je ustavila.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The motor protection tripped (a blunt cutter, too much feed).</source>
        <translation>Sprožila se je motorska zaščita (top rezkar, preveliko podajanje).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The part-present sensor lost the board while the cycle was using it.</source>
        <translation>Senzor prisotnosti deske je izgubil desko, medtem ko jo je cikel uporabljal.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The recipe&apos;s stave does not fit this machine.</source>
        <translation>Doga iz recepta ne ustreza temu stroju.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The recipe&apos;s values give no shape for this width.</source>
        <translation>Vrednosti recepta za to širino ne dajo oblike.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The screen was busy or frozen.</source>
        <translation>Zaslon je bil zaseden ali zamrznjen.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The sensor is dirty or misadjusted.</source>
        <translation>Senzor je umazan ali slabo nastavljen.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The spindle did not report running in time; nothing was cut.</source>
        <translation>Vreteno ni pravočasno sporočilo, da teče; nič ni bilo odrezano.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The spindle stopped during a cut; the axes were stopped at once.</source>
        <translation>Vreteno se je ustavilo med rezanjem; osi so bile takoj ustavljene.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The spindle&apos;s contactor or its running signal is faulty.</source>
        <translation>Kontaktor vretena ali njegov signal delovanja je okvarjen.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The spindle&apos;s motor protection tripped.</source>
        <translation>Sprožila se je motorska zaščita vretena.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The supply of the spindle dropped.</source>
        <translation>Napajanje vretena je izpadlo.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The touch was lost while holding the button.</source>
        <translation>Med držanjem gumba se je dotik izgubil.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The way to the cut would take the cutter through the board; nothing moved.</source>
        <translation>Pot do reza bi vodila rezkar skozi desko; nič se ni premaknilo.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The width gauge sent no measurement in time; the board was not cut.</source>
        <translation>Merilnik širine ni pravočasno poslal meritve; deska ni bila odrezana.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The width gauge sent something that is not a width.</source>
        <translation>Merilnik širine je poslal nekaj, kar ni širina.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The width gauge&apos;s connection is gone; no board can be measured.</source>
        <translation>Povezave z merilnikom širine ni več; nobene deske ni mogoče izmeriti.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The wrong recipe is selected.</source>
        <translation>Izbran je napačen recept.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Too many wrong PINs were entered; PIN entry waits before it accepts another.</source>
        <translation>Vnesenih je bilo preveč napačnih PIN-ov; vnos PIN počaka, preden sprejme novega.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Tool path could not be planned</source>
        <translation>Poti orodja ni bilo mogoče načrtovati</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tool path outside the axis travel</source>
        <translation>Pot orodja je zunaj hoda osi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wait until the lock ends, then enter the right PIN.</source>
        <translation>Počakajte, da se zaklep konča, nato vnesite pravi PIN.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Width gauge disconnected</source>
        <translation>Merilnik širine je odklopljen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Width gauge gave no reading</source>
        <translation>Merilnik širine ni dal meritve</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Width gauge reading not understood</source>
        <translation>Meritev merilnika širine ni razumljiva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wrong serial settings or a faulty cable.</source>
        <translation>Napačne nastavitve serijskih vrat ali okvarjen kabel.</translation>
    </message>
</context>
<context>
    <name>AlarmsScreen</name>
    <message>
        <location filename="../../app/screens/alarms_screen.py" line="+170"/>
        <source>Alarms</source>
        <translation>Alarmi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Active alarms</source>
        <translation>Aktivni alarmi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acknowledge all</source>
        <translation>Potrdi vse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset machine</source>
        <translation>Ponastavi stroj</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No active alarms.</source>
        <translation>Ni aktivnih alarmov.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>History</source>
        <translation>Zgodovina</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 hour</source>
        <translation>1 ura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>24 hours</source>
        <translation>24 ur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>7 days</source>
        <translation>7 dni</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All</source>
        <translation>Vse</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Code: %1</source>
        <translation>Koda: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+3"/>
        <source>all</source>
        <translation>vse</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Source: %1</source>
        <translation>Vir: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+10"/>
        <source>Time</source>
        <translation>Čas</translation>
    </message>
    <message>
        <location line="-9"/>
        <location line="+10"/>
        <source>Code</source>
        <translation>Koda</translation>
    </message>
    <message>
        <location line="-9"/>
        <location line="+10"/>
        <source>Alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <location line="-9"/>
        <location line="+10"/>
        <location line="+124"/>
        <source>Source</source>
        <translation>Vir</translation>
    </message>
    <message>
        <location line="-133"/>
        <source>State</source>
        <translation>Stanje</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>New state</source>
        <translation>Novo stanje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>User</source>
        <translation>Uporabnik</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Acknowledge</source>
        <translation>Potrdi</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>All codes</source>
        <translation>Vse kode</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Alarm code</source>
        <translation>Koda alarma</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>All sources</source>
        <translation>Vsi viri</translation>
    </message>
</context>
<context>
    <name>BarrelOverlay</name>
    <message>
        <location filename="../../app/screens/barrel_overlay.py" line="+31"/>
        <source>Close</source>
        <translation>Zapri</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Barrel %1</source>
        <translation>Sod %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Staves: %1</source>
        <translation>Dog: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Closed</source>
        <translation>Zaprt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The next board is stave 1.</source>
        <translation>Naslednja deska je doga 1.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Gap %1</source>
        <translation>Reža %1</translation>
    </message>
</context>
<context>
    <name>BarrelPanel</name>
    <message>
        <location filename="../../app/screens/barrel_panel.py" line="+94"/>
        <source>Closing stave</source>
        <translation>Zapri sod zdaj</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One more stave</source>
        <translation>Še ena doga</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+98"/>
        <source>Cooper&apos;s card</source>
        <translation>Kartica soda</translation>
    </message>
    <message>
        <location line="-42"/>
        <source>No barrel is being raised</source>
        <translation>Noben sod ni v delu</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Start a barrel</source>
        <translation>Začni sod</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>New barrel</source>
        <translation>Nov sod</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Barrel %1</source>
        <translation>Sod %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Staves: %1</source>
        <translation>Dog: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Closed</source>
        <translation>Zaprt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The next board starts a new barrel.</source>
        <translation>Naslednja deska začne nov sod.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The next board is stave 1.</source>
        <translation>Naslednja deska je doga 1.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Left %1 · gap %2</source>
        <translation>Ostane %1 · reža %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>About %1 more staves</source>
        <translation>Še približno %1 dog</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>A stave of %1 closes it. Next board:</source>
        <translation>Doga širine %1 ga zapre. Naslednja deska:</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Card not written: %1</source>
        <translation>Kartica ni zapisana: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cooper&apos;s card written to %1.</source>
        <translation>Sodarjeva kartica zapisana v %1.</translation>
    </message>
</context>
<context>
    <name>ChoiceOverlay</name>
    <message>
        <location filename="../../app/screens/widgets/dialogs.py" line="+125"/>
        <source>Cancel</source>
        <translation>Prekliči</translation>
    </message>
</context>
<context>
    <name>ConfirmOverlay</name>
    <message>
        <location line="-65"/>
        <source>Cancel</source>
        <translation>Prekliči</translation>
    </message>
</context>
<context>
    <name>FeedOverride</name>
    <message>
        <location filename="../../app/screens/widgets/feed_override.py" line="+71"/>
        <source>Feed override</source>
        <translation>Korekcija podajanja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slower by 10 %</source>
        <translation>Počasneje za 10 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Faster by 10 %</source>
        <translation>Hitreje za 10 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The recipe&apos;s feed</source>
        <translation>Podajanje iz recepta</translation>
    </message>
</context>
<context>
    <name>FileChooser</name>
    <message>
        <location filename="../../app/screens/widgets/file_chooser.py" line="+85"/>
        <source>▲ Up</source>
        <translation>▲ Gor</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Home</source>
        <translation>Domača mapa</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Cancel</source>
        <translation>Prekliči</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Save here</source>
        <translation>Shrani sem</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Open</source>
        <translation>Odpri</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>File name</source>
        <translation>Ime datoteke</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>A file name cannot contain &apos;/&apos;.</source>
        <translation>Ime datoteke ne sme vsebovati &apos;/&apos;.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The file name must end in %1.</source>
        <translation>Ime datoteke se mora končati s %1.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> or </source>
        <translation> ali </translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Choose a file first.</source>
        <translation>Najprej izberite datoteko.</translation>
    </message>
</context>
<context>
    <name>IoScreen</name>
    <message>
        <location filename="../../app/screens/io_screen.py" line="+103"/>
        <location line="+3"/>
        <source>Inputs and outputs</source>
        <translation>Vhodi in izhodi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inputs</source>
        <translation>Vhodi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Outputs</source>
        <translation>Izhodi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Back</source>
        <translation>Nazaj</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>not wired</source>
        <translation>ni priključen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>simulated</source>
        <translation>simulirano</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Backend: %1</source>
        <translation>Krmilje: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>ON</source>
        <translation>VKLOP</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>off</source>
        <translation>izklop</translation>
    </message>
</context>
<context>
    <name>IoSignals</name>
    <message>
        <location filename="../../app/screens/io_status.py" line="+26"/>
        <source>Spindle</source>
        <translation>Vreteno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clamps</source>
        <translation>Vpenjala</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Centering</source>
        <translation>Centriranje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Board</source>
        <translation>Deska</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Guard</source>
        <translation>Zaščita</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>E-stop chain</source>
        <translation>Veriga zasilne zaustavitve</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>running</source>
        <translation>teče</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopped</source>
        <translation>stoji</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>closed</source>
        <translation>zaprta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>open</source>
        <translation>odprta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OPEN</source>
        <translation>ODPRTA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>moving</source>
        <translation>v gibanju</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>extended</source>
        <translation>izvlečeno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>retracted</source>
        <translation>uvlečeno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>present</source>
        <translation>vložena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none</source>
        <translation>ni je</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OK</source>
        <translation>v redu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>BROKEN</source>
        <translation>PREKINJENA</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>Board present</source>
        <translation>Deska vložena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Centering extended</source>
        <translation>Centriranje izvlečeno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Centering retracted</source>
        <translation>Centriranje uvlečeno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clamps closed</source>
        <translation>Vpenjala zaprta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clamps open</source>
        <translation>Vpenjala odprta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spindle running</source>
        <translation>Vreteno teče</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Guard closed</source>
        <translation>Zaščita zaprta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>E-stop chain closed</source>
        <translation>Veriga zasilne zaustavitve sklenjena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start push button</source>
        <translation>Tipka Start</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop push button</source>
        <translation>Tipka Stop</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset push button</source>
        <translation>Tipka Ponastavi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Handwheel selector X</source>
        <translation>Izbirnik ročnega kolesa X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Handwheel selector Y</source>
        <translation>Izbirnik ročnega kolesa Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Handwheel selector Z (tilt)</source>
        <translation>Izbirnik ročnega kolesa Z (nagib)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Handwheel multiplier x10</source>
        <translation>Množilnik ročnega kolesa x10</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Handwheel multiplier x100</source>
        <translation>Množilnik ročnega kolesa x100</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jog enable button</source>
        <translation>Tipka za omogočanje premikanja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Extend centering</source>
        <translation>Izvleci centriranje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close clamps</source>
        <translation>Zapri vpenjala</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spindle contactor</source>
        <translation>Kontaktor vretena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Green lamp</source>
        <translation>Zelena luč</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yellow lamp</source>
        <translation>Rumena luč</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Red lamp</source>
        <translation>Rdeča luč</translation>
    </message>
</context>
<context>
    <name>Keypad</name>
    <message>
        <location filename="../../app/screens/widgets/keypad.py" line="+284"/>
        <source>Cancel</source>
        <translation>Prekliči</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OK</source>
        <translation>V redu</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Allowed: whole number from %1 to %2%3</source>
        <translation>Dovoljeno: celo število od %1 do %2%3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Allowed: %1 to %2%3, or empty</source>
        <translation>Dovoljeno: od %1 do %2%3 ali prazno</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Allowed: %1 to %2%3</source>
        <translation>Dovoljeno: od %1 do %2%3</translation>
    </message>
    <message>
        <location line="+118"/>
        <source>Enter a number. %1</source>
        <translation>Vnesite število. %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1%2 is outside the allowed range.</source>
        <translation>%1%2 je zunaj dovoljenega območja.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Enter both the numerator and the denominator.</source>
        <translation>Vnesite števec in imenovalec.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The denominator must not be 0.</source>
        <translation>Imenovalec ne sme biti 0.</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Enter your PIN.</source>
        <translation>Vnesite PIN.</translation>
    </message>
</context>
<context>
    <name>MachineText</name>
    <message>
        <location filename="catalogue_strings.py" line="-419"/>
        <source>%1</source>
        <translation>%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is not possible while %2</source>
        <translation>%1 ni mogoče v stanju %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 still in fault %2</source>
        <translation>%1 je še vedno v napaki %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1+ limit switch is active: jog %1 in the - direction only</source>
        <translation>končno stikalo %1+ je aktivno: %1 premikajte samo v smeri -</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1- limit switch is active: jog %1 in the + direction only</source>
        <translation>končno stikalo %1- je aktivno: %1 premikajte samo v smeri +</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: Resume or Abandon</source>
        <translation>%1: nadaljujte ali opustite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DC link over-voltage</source>
        <translation>prenapetost v enosmernem vmesnem krogu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>USB pendant ignored: it jogs only on the Manual screen</source>
        <translation>USB-upravljalnik ni upoštevan: premika samo na zaslonu Ročno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a board is on the table and not clamped: clamp it or take it off before the spindle starts</source>
        <translation>na mizi je deska, ki ni vpeta: vpnite jo ali jo odstranite, preden se vreteno zažene</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a board is on the table and the axes do not know where they are: take the board off before homing</source>
        <translation>na mizi je deska, osi pa ne vedo, kje so: pred referenciranjem odstranite desko</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a board is on the table: moving clear of it before homing</source>
        <translation>na mizi je deska: pred referenciranjem se umikam od nje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a board is partly cut: Resume or Abandon it</source>
        <translation>deska je delno obdelana: nadaljujte ali jo opustite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a board is partly cut: Resume or Abandon it first</source>
        <translation>deska je delno obdelana: najprej nadaljujte ali jo opustite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a cycle is already running</source>
        <translation>cikel že teče</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a step of 0 moves nothing</source>
        <translation>korak 0 ničesar ne premakne</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>abandoning the board</source>
        <translation>opuščanje deske</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>already in manual mode</source>
        <translation>stroj je že v ročnem načinu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an axis lost its home position</source>
        <translation>os je izgubila referenčno lego</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axes are not homed: abandon the board (their position is unknown)</source>
        <translation>osi niso referencirane: opustite desko (njihov položaj ni znan)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>axes are not homed: home the machine first</source>
        <translation>osi niso referencirane: najprej referencirajte stroj</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>axis %1 is at its lower soft limit %2</source>
        <translation>os %1 je na spodnji programski meji %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1 is at its soft limit</source>
        <translation>os %1 je na programski meji</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>axis %1 is above its upper soft limit %2 (at %3): only motion back toward the range is allowed</source>
        <oldsource>axis %1 is beyond its soft limit %2 = %3 (%4): only motion back toward the range is allowed</oldsource>
        <translation>os %1 je nad zgornjo programsko mejo %2 (na %3): dovoljen je le premik nazaj proti območju</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>axis %1 is at its upper soft limit %2</source>
        <translation>os %1 je na zgornji programski meji %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1 is below its lower soft limit %2 (at %3): only motion back toward the range is allowed</source>
        <translation>os %1 je pod spodnjo programsko mejo %2 (na %3): dovoljen je le premik nazaj proti območju</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>axis %1 is moving: release the jog first</source>
        <translation>os %1 se premika: najprej spustite ročni premik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1 is not allowed: X, Y or Z</source>
        <translation>os %1 ni dovoljena: X, Y ali Z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1 stopped: the screen stopped confirming the jog</source>
        <translation>os %1 ustavljena: zaslon ni več potrjeval ročnega premika</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1, fault code %2</source>
        <translation>os %1, koda napake %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1: drive did not enable within %2 s</source>
        <translation>os %1: pogon se ni vklopil v %2 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1: drive fault %2 while homing</source>
        <translation>os %1: napaka pogona %2 med referenciranjem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1: drive not enabled while moving (%2)</source>
        <translation>os %1: pogon med gibanjem ni vklopljen (%2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1: following error %2 %3 exceeds %4 %3</source>
        <translation>os %1: pogrešek sledenja %2 %3 presega %4 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1: homing did not start within %2 s</source>
        <translation>os %1: referenciranje se ni začelo v %2 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1: homing ended without finding the home switch</source>
        <translation>os %1: referenciranje se je končalo, ne da bi našlo referenčno stikalo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1: negative limit switch at %2 %3</source>
        <translation>os %1: negativno končno stikalo pri %2 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1: no feedback from its drive</source>
        <translation>os %1: ni povratne informacije od pogona</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1: not homed after %2 s</source>
        <translation>os %1: po %2 s ni referencirana</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1: positive limit switch at %2 %3</source>
        <translation>os %1: pozitivno končno stikalo pri %2 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis %1: setpoint %2 %3 outside the travel %4 to %5 %3</source>
        <translation>os %1: zahtevana lega %2 %3 je zunaj hoda od %4 do %5 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>board abandoned and unclamped: take it off (nothing moved: check that the cutter is clear of it)</source>
        <translation>deska opuščena in odpeta: odstranite jo (nič se ni premaknilo: preverite, da rezkar ni na njej)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>board abandoned: take it off</source>
        <translation>deska opuščena: odstranite jo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>centering device not extended after %1 s</source>
        <translation>centrirna naprava po %1 s ni iztegnjena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>centering device not retracted after %1 s</source>
        <translation>centrirna naprava po %1 s ni umaknjena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>clamps not closed after %1 s</source>
        <translation>vpenjala po %1 s niso zaprta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>clamps not open after %1 s</source>
        <translation>vpenjala po %1 s niso odprta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>clipped to the lower soft limit %1</source>
        <translation>omejeno na spodnjo programsko mejo %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>clipped to the upper soft limit %1</source>
        <translation>omejeno na zgornjo programsko mejo %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>close the guard first</source>
        <translation>najprej zaprite zaščito</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>communication not restored</source>
        <translation>komunikacija ni obnovljena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drive over-temperature</source>
        <translation>previsoka temperatura pogona</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>emergency stop still pressed</source>
        <translation>zasilna zaustavitev je še pritisnjena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feed override %1 % is not allowed: 0 to 120 %</source>
        <translation>korekcija podajanja %1 % ni dovoljena: 0 do 120 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>following error</source>
        <translation>pogrešek sledenja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>go to position refused: %1</source>
        <translation>premik na položaj zavrnjen: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>go to position: %1 = %2 is not allowed: %3 to %4</source>
        <translation>premik na položaj: %1 = %2 ni dovoljeno: %3 do %4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>handwheel ignored: it jogs only on the Manual screen</source>
        <translation>ročno kolo ni upoštevano: premika samo na zaslonu Ročno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>heartbeat or life guard</source>
        <translation>nadzor delovanja (heartbeat ali life guard)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hold the enable button to jog with the handwheel or the joystick</source>
        <translation>za premikanje z ročnim kolesom ali igralno palico držite tipko za omogočanje</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>homing refused: %1</source>
        <translation>referenciranje zavrnjeno: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>jog %1 refused: the cutter is at the board&apos;s keep-out (a board is on the table)</source>
        <translation>ročni premik %1 zavrnjen: rezilo je na meji zaščitnega območja deske (na mizi je deska)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>jog %1 stops at %2, the edge of the board&apos;s keep-out</source>
        <translation>ročni premik %1 se ustavi pri %2, na meji zaščitnega območja deske</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>jog %1 was stopped: no refresh from the screen for %2 s; release the button and press it again</source>
        <translation>ročni premik %1 je bil ustavljen: zaslon %2 s ni osvežil ukaza; spustite tipko in jo pritisnite znova</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>jog direction %1 is not allowed: -1 or 1</source>
        <translation>smer ročnega premika %1 ni dovoljena: -1 ali 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>joystick %1 reads %2 counts off its centre at start-up: let it go, it is calibrated once at rest</source>
        <translation>igralna palica %1 je ob zagonu %2 enot od središča: spustite jo, umeri se, ko miruje</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>joystick ignored: it jogs only on the Manual screen</source>
        <translation>igralna palica ni upoštevana: premika samo na zaslonu Ročno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>leave manual mode first</source>
        <translation>najprej zapustite ročni način</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>limit switch</source>
        <translation>končno stikalo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>machine is busy (automatic): stop it first</source>
        <translation>stroj je zaseden (avtomatika): najprej ga ustavite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>machine is busy (homing): stop it first</source>
        <translation>stroj je zaseden (referenciranje): najprej ga ustavite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>machine is busy (stopping): stop it first</source>
        <translation>stroj je zaseden (ustavljanje): najprej ga ustavite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>machine is in emergency stop: press Reset first</source>
        <translation>stroj je v zasilni zaustavitvi: najprej pritisnite Ponastavi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>machine is in emergency stop: release the emergency stop button, then press Reset</source>
        <translation>stroj je v zasilni zaustavitvi: sprostite tipko za zasilno zaustavitev, nato pritisnite Ponastavi</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>machine is in error: press Reset first</source>
        <translation>stroj je v napaki: najprej pritisnite Ponastavi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>machine is still starting up</source>
        <translation>stroj se še zaganja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no board is partly cut</source>
        <translation>nobena deska ni delno odrezana</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no connection to the machine</source>
        <translation>ni povezave s strojem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no reading within %1 s</source>
        <translation>ni meritve v %1 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not in manual mode</source>
        <translation>stroj ni v ročnem načinu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not possible while automatic</source>
        <translation>ni mogoče med avtomatiko</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not possible while homing</source>
        <translation>ni mogoče med referenciranjem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not possible while manual</source>
        <translation>ni mogoče v ročnem načinu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not possible while not homed</source>
        <translation>ni mogoče, dokler osi niso referencirane</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not possible while ready</source>
        <translation>ni mogoče v stanju pripravljenosti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not possible while stopping</source>
        <translation>ni mogoče med ustavljanjem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nothing is moving</source>
        <translation>nič se ne premika</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nothing to reset</source>
        <translation>ničesar ni treba ponastaviti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>only on the simulated machine</source>
        <translation>samo na simuliranem stroju</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>open the Manual screen to jog</source>
        <translation>za ročni premik odprite zaslon Ročno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>over-current</source>
        <translation>prevelik tok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position sensor</source>
        <translation>senzor položaja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>recipe %1 does not exist</source>
        <translation>recept %1 ne obstaja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>recipe %1 has a fixed tilt: it makes no barrel</source>
        <translation>recept %1 ima stalen nagib: iz njega ne nastane sod</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>recipe %1 has been changed since it was selected: the machine keeps the version it was selected with; select it again to cut the new version</source>
        <translation>recept %1 je bil spremenjen, odkar je bil izbran: stroj obdrži različico, s katero je bil izbran; izberite ga znova, da bo rezal novo različico</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>recipe %1 no longer exists: abandon the board</source>
        <translation>recept %1 ne obstaja več: opustite desko</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>recipe %1, selected on the machine, has been deleted: select a recipe</source>
        <translation>recept %1, izbran na stroju, je bil izbrisan: izberite recept</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>reconnection failed: %1</source>
        <translation>ponovna povezava ni uspela: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>release the emergency stop first</source>
        <translation>najprej sprostite zasilno zaustavitev</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reset done</source>
        <translation>ponastavitev opravljena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reset failed</source>
        <translation>ponastavitev ni uspela</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>resuming the board</source>
        <translation>nadaljevanje deske</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>select a recipe first</source>
        <translation>najprej izberite recept</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>spindle not running after %1 s</source>
        <translation>vreteno po %1 s ne teče</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>step of %1 refused: the cutter would enter the board&apos;s keep-out at %2 (a board is on the table)</source>
        <translation>korak %1 zavrnjen: rezilo bi pri %2 vstopilo v zaščitno območje deske (na mizi je deska)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the USB pendant is jogging: let it and the axes come to rest first</source>
        <translation>USB-upravljalnik premika: najprej naj se umiri on in osi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the axes are going to a position: wait, or press Stop</source>
        <translation>osi se premikajo na položaj: počakajte ali pritisnite Stop</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the board is clamped: unclamp it first</source>
        <translation>deska je vpeta: najprej jo sprostite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the board was unclamped: it may have moved, abandon it</source>
        <translation>deska je bila odpeta: morda se je premaknila, opustite jo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the counter moved %1 counts in one read; a hand turns at most %2</source>
        <translation>števec se je v enem branju premaknil za %1 enot; roka zavrti največ %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the guard was opened</source>
        <translation>zaščita je bila odprta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the handwheel is jogging: let it and the axes come to rest first</source>
        <translation>ročno kolo premika: najprej naj se umiri ono in osi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the joystick is jogging: let it go and the axes stop first</source>
        <translation>igralna palica premika: najprej jo spustite in počakajte, da se osi ustavijo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the oldest has waited %1 s</source>
        <translation>najstarejši čaka že %1 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the part-present sensor went off during the cycle</source>
        <translation>senzor prisotnosti deske se je med ciklom izklopil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the partly cut board is no longer on the table</source>
        <translation>delno odrezane deske ni več na mizi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the recipe selected before the restart cannot be read: select a recipe</source>
        <translation>recepta, izbranega pred ponovnim zagonom, ni mogoče prebrati: izberite recept</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the screen is jogging: release it and let the axes stop first</source>
        <translation>zaslon premika: najprej spustite tipko in počakajte, da se osi ustavijo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the simulation refused: %1</source>
        <translation>simulacija je zavrnila: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the spindle&apos;s running signal went off</source>
        <translation>signal delovanja vretena je izpadel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown command</source>
        <translation>neznan ukaz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wait until the cycle has ended</source>
        <translation>počakajte, da se cikel konča</translation>
    </message>
</context>
<context>
    <name>MainScreen</name>
    <message>
        <location filename="../../app/screens/main_screen.py" line="+282"/>
        <source>Main</source>
        <translation>Glavni</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Recipe</source>
        <translation>Recept</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose recipe…</source>
        <translation>Izberi recept…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Previous recipe</source>
        <translation>Prejšnji recept</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Next recipe</source>
        <translation>Naslednji recept</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>▶  START</source>
        <translation>▶  ZAGON</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>■  STOP</source>
        <translation>■  USTAVI</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Home</source>
        <translation>Referenciraj</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset</source>
        <translation>Ponastavi</translation>
    </message>
    <message>
        <location line="-24"/>
        <source>Put a board in
(simulation)</source>
        <translation>Vstavi desko
(simulacija)</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Replace the board
(simulation)</source>
        <translation>Zamenjaj desko
(simulacija)</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>New
shift</source>
        <translation>Nova
izmena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pieces this shift</source>
        <translation>Kosov v izmeni</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pieces total</source>
        <translation>Kosov skupaj</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+169"/>
        <source>Last width</source>
        <translation>Zadnja širina</translation>
    </message>
    <message>
        <location line="-168"/>
        <source>Last cycle</source>
        <translation>Zadnji cikel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cycle</source>
        <translation>Cikel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Waited</source>
        <translation>Čakanje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remaining</source>
        <translation>Preostalo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>All inputs and outputs</source>
        <translation>Vsi vhodi in izhodi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Last cycle by step</source>
        <translation>Zadnji cikel po korakih</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>NOT HOMED</source>
        <translation>NI REFERENCIRANO</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>There are no recipes yet: create one on Recipes.</source>
        <translation>Receptov še ni: ustvarite ga na zaslonu Recepti.</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Resume the cut</source>
        <translation>Nadaljuj rezanje</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Abandon the board</source>
        <translation>Opusti desko</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>A board is partly cut</source>
        <translation>Deska je delno odrezana</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>New shift</source>
        <translation>Nova izmena</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start counting the pieces of a new shift from 0? The total count is kept; the operator of the new shift then enters his name.</source>
        <translation>Začnem štetje kosov nove izmene od 0? Skupno število ostane; upravljavec nove izmene nato vpiše svoje ime.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Start new shift</source>
        <translation>Začni novo izmeno</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>No recipe selected</source>
        <translation>Ni izbranega recepta</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No. %1</source>
        <translation>Št. %1</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>+%1 waiting</source>
        <translation>+%1 čakanja</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Board width</source>
        <translation>Širina deske</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Take the finished board off</source>
        <translation>Odstranite obdelano desko</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No cycle running</source>
        <translation>Cikel ne teče</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Move to go</source>
        <translation>Ostanek giba</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step to go</source>
        <translation>Ostanek koraka</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Path speed</source>
        <translation>Hitrost</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Moving clear of the board</source>
        <translation>Umik od deske</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Homing axis %1</source>
        <translation>Referenciranje osi %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Homing done</source>
        <translation>Referenciranje končano</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Axis %1</source>
        <translation>Os %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>homed ✓</source>
        <translation>referencirana ✓</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>homing…</source>
        <translation>se referencira…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>waiting</source>
        <translation>čaka</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../../app/screens/main_window.py" line="+190"/>
        <source>(+%1 more)</source>
        <translation>(+%1 drugih)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+204"/>
        <source>Alarms</source>
        <translation>Alarmi</translation>
    </message>
    <message>
        <location line="-197"/>
        <source>The machine is not running.</source>
        <translation>Stroj ne deluje.</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Service</source>
        <translation>Servis</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+7"/>
        <location line="+4"/>
        <source>Log out</source>
        <translation>Odjava</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+213"/>
        <location line="+2"/>
        <source>Leave the kiosk</source>
        <translation>Zapusti kiosk</translation>
    </message>
    <message>
        <location line="-207"/>
        <source>Log out %1 and go back to the operator level?</source>
        <translation>Odjavim uporabnika %1 in se vrnem na raven operaterja?</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>User</source>
        <translation>Uporabnik</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Log in with a PIN</source>
        <translation>Prijava s PIN-om</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Name the operator of this shift</source>
        <translation>Vpiši upravljavca te izmene</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Log in: enter your PIN</source>
        <translation>Prijava: vnesite PIN</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Operator of this shift: your name</source>
        <translation>Upravljavec te izmene: vaše ime</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Wrong PIN.</source>
        <translation>Napačen PIN.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>This needs the %1 level; %2 is %3.</source>
        <translation>Potrebna je raven %1; %2 ima raven %3.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Checking…</source>
        <translation>Preverjam…</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>This needs the %1 level: enter a PIN</source>
        <translation>Potrebna je raven %1: vnesite PIN</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Operator of this shift: %1</source>
        <translation>Upravljavec te izmene: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Logged out.</source>
        <translation>Odjavljen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Logged in: %1 (%2)</source>
        <translation>Prijavljen: %1 (%2)</translation>
    </message>
    <message>
        <location line="+20"/>
        <location line="+23"/>
        <source>Language</source>
        <translation>Jezik</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>Main</source>
        <translation>Glavni</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recipes</source>
        <translation>Recepti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>System</source>
        <translation>Sistem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Manual</source>
        <translation>Ročno</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Production</source>
        <translation>Proizvodnja</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+57"/>
        <location line="+2"/>
        <source>Shut down</source>
        <translation>Izklop</translation>
    </message>
    <message>
        <location line="-58"/>
        <source>Log in or out</source>
        <translation>Prijava ali odjava</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stave jointer</source>
        <translation>Stroj za obdelavo dog</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Stop the machine safely and leave the operator screen for the console?</source>
        <translation>Varno ustavim stroj in zapustim operaterski zaslon za konzolo?</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Stop the machine safely and close the program?</source>
        <translation>Varno ustavim stroj in zaprem program?</translation>
    </message>
</context>
<context>
    <name>ManualScreen</name>
    <message>
        <location filename="../../app/screens/manual_screen.py" line="+235"/>
        <source>Manual</source>
        <translation>Ročno</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Enter manual mode</source>
        <translation>Vstopi v ročni način</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tilt</source>
        <translation>Nagib</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Continuous</source>
        <translation>Zvezno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step</source>
        <translation>Korak</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step size (mm for X-Y; tilt 0.1° or 1°)</source>
        <translation>Velikost koraka (mm za X-Y; nagib 0,1° ali 1°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jog speed</source>
        <translation>Hitrost ročnega premika</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jog acceleration</source>
        <translation>Pospešek ročnega premika</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Home (find the reference position)</source>
        <translation>Referenciranje (iskanje referenčne lege)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Home %1</source>
        <translation>Referenciraj %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go to…</source>
        <translation>Pojdi na…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go to a position typed on the keypad</source>
        <translation>Premik na položaj, vpisan na tipkovnici</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All</source>
        <translation>Vse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Home all axes</source>
        <translation>Referenciraj vse osi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>NOT HOMED</source>
        <translation>NI REFERENCIRANO</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Waiting for the machine…</source>
        <translation>Čakam na stroj…</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Jog speed %1</source>
        <translation>Hitrost ročnega premika %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog acceleration %1</source>
        <translation>Pospešek ročnega premika %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Log in to change parameters.</source>
        <translation>Za spreminjanje parametrov se prijavite.</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Go to X</source>
        <translation>Premik na X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go to Y</source>
        <translation>Premik na Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go to tilt</source>
        <translation>Premik na nagib</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Start the spindle?</source>
        <translation>Zaženem vreteno?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The cutter starts turning. Keep clear of it.</source>
        <translation>Rezilo se začne vrteti. Ne približujte se mu.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Manual mode: hold a button to jog.</source>
        <translation>Ročni način: za premik držite gumb.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Not in manual mode.</source>
        <translation>Stroj ni v ročnem načinu.</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Open clamps</source>
        <translation>Odpri vpenjala</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Close clamps</source>
        <translation>Zapri vpenjala</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Spindle OFF</source>
        <translation>Vreteno IZKLOP</translation>
    </message>
    <message>
        <location line="-64"/>
        <location line="+64"/>
        <source>Spindle ON</source>
        <translation>Vreteno VKLOP</translation>
    </message>
</context>
<context>
    <name>MessageOverlay</name>
    <message>
        <location filename="../../app/screens/widgets/dialogs.py" line="+21"/>
        <source>OK</source>
        <translation>V redu</translation>
    </message>
</context>
<context>
    <name>OpcuaPage</name>
    <message>
        <location filename="../../app/screens/opcua_page.py" line="+89"/>
        <source>OPC UA plant connection</source>
        <translation>Povezava OPC UA z obratom</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Client certificates refused (not trusted yet). A plant system connects only after its certificate is trusted:</source>
        <translation>Zavrnjena potrdila odjemalcev (še niso zaupanja vredna). Sistem obrata se poveže šele, ko njegovo potrdilo označite kot zaupanja vredno:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Certificate</source>
        <translation>Potrdilo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Application</source>
        <translation>Aplikacija</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Valid until</source>
        <translation>Veljavno do</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Trust the selected certificate</source>
        <translation>Zaupaj izbranemu potrdilu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Refresh</source>
        <translation>Osveži</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Server off ([opcua] enabled = false in the configuration).</source>
        <translation>Strežnik izklopljen ([opcua] enabled = false v konfiguraciji).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Server running: plant systems can connect.</source>
        <translation>Strežnik teče: sistemi obrata se lahko povežejo.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Server not running: %1</source>
        <translation>Strežnik ne teče: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Server not running: its process has ended (see opcua.log).</source>
        <translation>Strežnik ne teče: njegov proces se je končal (glejte opcua.log).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Server starting (loading the information model)...</source>
        <translation>Strežnik se zaganja (nalaga informacijski model) ...</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Warning: security policy None is on: clients may connect without signing or encryption.</source>
        <translation>Opozorilo: varnostna politika None je vklopljena: odjemalci se lahko povežejo brez podpisa in šifriranja.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Warning: anonymous access is on: clients may read without a user.</source>
        <translation>Opozorilo: anonimni dostop je vklopljen: odjemalci lahko berejo brez uporabnika.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Use these for commissioning only ([opcua] configuration).</source>
        <translation>To uporabljajte samo za zagon naprave (konfiguracija [opcua]).</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Endpoint: %1</source>
        <translation>Končna točka: %1</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>Certificate %1 trusted by %2 (logged).</source>
        <translation>Potrdilo %1 je označil kot zaupanja vredno %2 (zabeleženo).</translation>
    </message>
</context>
<context>
    <name>Parameters</name>
    <message>
        <location filename="catalogue_strings.py" line="+251"/>
        <source>Distance beyond the board&apos;s right end where the tilt changes sides</source>
        <translation>Razdalja za desnim koncem deske, kjer se nagib zamenja</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Height of the tilt pivot above the table (Hm)</source>
        <translation>Višina osi nagiba nad mizo (Hm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Home position of X</source>
        <translation>Referenčna lega X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Home position of Y</source>
        <translation>Referenčna lega Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Home tilt of the router (Z)</source>
        <translation>Referenčni nagib rezkarja (Z)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lead-in before x = 0 and lead-out after x = L (longer than the tool radius)</source>
        <translation>Uvod pred x = 0 in izvod za x = L (daljša od polmera orodja)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Length of one shift</source>
        <translation>Dolžina ene izmene</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Most material the router takes off one side in one pass (more: roughing passes first)</source>
        <translation>Največ materiala, ki ga rezkar odvzame z ene strani v enem prehodu (več: najprej grobi prehodi)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Number of shifts per day</source>
        <translation>Število izmen na dan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P0: machine X of the stave&apos;s left end</source>
        <translation>P0: strojni X levega konca doge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P0: machine Y of the table centre line</source>
        <translation>P0: strojni Y srednjice mize</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius of the router cutter</source>
        <translation>Polmer rezkarja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Soft limit: highest X</source>
        <translation>Programska meja: največji X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Soft limit: highest Y</source>
        <translation>Programska meja: največji Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Soft limit: highest tilt</source>
        <translation>Programska meja: največji nagib</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Soft limit: lowest X</source>
        <translation>Programska meja: najmanjši X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Soft limit: lowest Y</source>
        <translation>Programska meja: najmanjši Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Soft limit: lowest tilt</source>
        <translation>Programska meja: najmanjši nagib</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start of the first shift of the day, hours after midnight (6.5 = 06:30)</source>
        <translation>Začetek prve izmene dneva, ure po polnoči (6.5 = 06:30)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Tilt (Z) acceleration</source>
        <translation>Pospešek nagiba (Z)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tilt (Z) jerk limit</source>
        <translation>Omejitev sunka nagiba (Z)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tilt (Z) jog acceleration</source>
        <translation>Pospešek ročnega nagiba (Z)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tilt (Z) jog speed</source>
        <translation>Hitrost ročnega nagiba (Z)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tilt (Z) speed</source>
        <translation>Hitrost nagiba (Z)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tolerance of the stave-side solver (root of the cubic in D)</source>
        <translation>Toleranca izračuna stranice doge (koren kubične enačbe za D)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X-Y acceleration</source>
        <translation>Pospešek X-Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X-Y cutting feed</source>
        <translation>Podajanje rezanja X-Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X-Y jerk limit</source>
        <translation>Omejitev sunka X-Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X-Y jog acceleration</source>
        <translation>Pospešek ročnega premika X-Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X-Y jog speed</source>
        <translation>Hitrost ročnega premika X-Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X-Y speed of non-cutting moves</source>
        <translation>Hitrost X-Y pri premikih brez rezanja</translation>
    </message>
</context>
<context>
    <name>PendantStatus</name>
    <message>
        <location filename="../../app/screens/widgets/pendant_status.py" line="+23"/>
        <source>the screen</source>
        <translation>zaslon</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the handwheel</source>
        <translation>ročno kolo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the joystick</source>
        <translation>igralna palica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the USB pendant</source>
        <translation>USB-upravljalnik</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>nobody (all at rest)</source>
        <translation>nihče (vse miruje)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Jogging: %1</source>
        <translation>Premika: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Handwheel: %1 ×%2</source>
        <translation>Ročno kolo: %1 ×%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Handwheel: off</source>
        <translation>Ročno kolo: izklopljeno</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>USB pendant connected</source>
        <translation>USB-upravljalnik priključen</translation>
    </message>
</context>
<context>
    <name>PinLockoutBar</name>
    <message>
        <location filename="../../app/screens/pin_lockout.py" line="+53"/>
        <source>Unlock PIN entry</source>
        <translation>Odkleni vnos PIN</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>PIN entry is locked after repeated wrong PINs until %1. A service user can unlock it now.</source>
        <translation>Vnos PIN je zaklenjen po ponavljajočih se napačnih PIN-ih do %1. Serviser ga lahko odklene zdaj.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>PIN entry unlocked by %1 (logged).</source>
        <translation>Vnos PIN je odklenil %1 (zabeleženo).</translation>
    </message>
</context>
<context>
    <name>ProductionScreen</name>
    <message>
        <location filename="../../app/screens/production_screen.py" line="+152"/>
        <source>Production</source>
        <translation>Proizvodnja</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>This shift</source>
        <translation>Ta izmena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Last shift</source>
        <translation>Prejšnja izmena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Today</source>
        <translation>Danes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>7 days</source>
        <translation>7 dni</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>30 days</source>
        <translation>30 dni</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export CSV…</source>
        <translation>Izvoz CSV…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Staves per hour</source>
        <translation>Dog na uro</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cycle time per stave, s:</source>
        <translation>Čas cikla na dogo, s:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cycle</source>
        <translation>cikel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bound</source>
        <translation>meja</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Board widths, mm</source>
        <translation>Širine desk, mm</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Alarms per hour</source>
        <translation>Alarmi na uro</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Good</source>
        <translation>Dobri</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Aborted</source>
        <translation>Prekinjeni</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rejected</source>
        <translation>Zavrnjeni</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 per hour</source>
        <translation>%1 na uro</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Alarms %1</source>
        <translation>Alarmi %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Reading…</source>
        <translation>Berem…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Nothing produced in this range.</source>
        <translation>V tem obdobju ni proizvodnje.</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Not read: %1</source>
        <translation>Ni prebrano: %1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Export production</source>
        <translation>Izvoz proizvodnje</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Export failed</source>
        <translation>Izvoz ni uspel</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 production records written to %2.</source>
        <translation>%1 zapisov proizvodnje zapisanih v %2.</translation>
    </message>
</context>
<context>
    <name>RecipeChooser</name>
    <message>
        <location filename="../../app/screens/recipe_chooser.py" line="+52"/>
        <source>Choose a recipe</source>
        <translation>Izberite recept</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cancel</source>
        <translation>Prekliči</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>No recipe matches.</source>
        <translation>Noben recept ne ustreza.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 of %2 recipes</source>
        <translation>%1 od %2 receptov</translation>
    </message>
</context>
<context>
    <name>RecipeFilterBar</name>
    <message>
        <location filename="../../app/screens/recipe_filter.py" line="+114"/>
        <source>All</source>
        <translation>Vsi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fixed</source>
        <translation>Stalen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Round</source>
        <translation>Okrogel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Oval</source>
        <translation>Ovalen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Show recipes of barrel type</source>
        <translation>Prikaži recepte za vrsto soda</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Search recipes by name or number</source>
        <translation>Iskanje receptov po imenu ali številki</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Search…</source>
        <translation>Iskanje…</translation>
    </message>
</context>
<context>
    <name>RecipesScreen</name>
    <message>
        <location filename="../../app/screens/recipes_screen.py" line="+379"/>
        <location line="+110"/>
        <source>Recipes</source>
        <translation>Recepti</translation>
    </message>
    <message>
        <location line="-106"/>
        <source>Name</source>
        <translation>Ime</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Length L</source>
        <translation>Dolžina L</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thickness H</source>
        <translation>Debelina H</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Length ratio L1 : L</source>
        <translation>Razmerje dolžin L1 : L</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Width ratio W1 : W</source>
        <translation>Razmerje širin W1 : W</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side profile</source>
        <translation>Stranski profil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Exponent n</source>
        <translation>Eksponent n</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Semi-axis a : L/2</source>
        <translation>Polos a : L/2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drawing (DXF)</source>
        <translation>Risba (DXF)</translation>
    </message>
    <message>
        <location line="+117"/>
        <source>Tilt</source>
        <translation>Nagib</translation>
    </message>
    <message>
        <location line="-115"/>
        <source>Tilt α</source>
        <translation>Nagib α</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Barrel diameter</source>
        <translation>Premer soda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Oval: short axis</source>
        <translation>Oval: kratka os</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Barrel perimeter</source>
        <translation>Obseg soda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Belly width to cut</source>
        <translation>Širina na trebuhu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Note</source>
        <translation>Opomba</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>(optional)</source>
        <translation>(neobvezno)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>0 to below 1/2</source>
        <translation>od 0 do manj kot 1/2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>1 to %1 characters</source>
        <translation>od 1 do %1 znakov</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>optional</source>
        <translation>neobvezno</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the shape of both sides</source>
        <translation>oblika obeh stranic</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>one side, head to head; scaled to L and W</source>
        <translation>ena stranica, od glave do glave; prilagojena L in W</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Line–arc–line</source>
        <translation>Premica–lok–premica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Single arc</source>
        <translation>En lok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parabola</source>
        <translation>Parabola</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ellipse arc</source>
        <translation>Eliptični lok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Superellipse</source>
        <translation>Superelipsa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drawn (DXF)</source>
        <translation>Narisan (DXF)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>New</source>
        <translation>Nov</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy</source>
        <translation>Kopiraj</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+641"/>
        <source>Delete</source>
        <translation>Izbriši</translation>
    </message>
    <message>
        <location line="-640"/>
        <location line="+690"/>
        <source>Import</source>
        <translation>Uvozi</translation>
    </message>
    <message>
        <location line="-689"/>
        <source>Export</source>
        <translation>Izvozi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save</source>
        <translation>Shrani</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+140"/>
        <source>Discard</source>
        <translation>Zavrzi</translation>
    </message>
    <message>
        <location line="-139"/>
        <source>Use on machine</source>
        <translation>Uporabi na stroju</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Preview</source>
        <translation>Predogled</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+447"/>
        <source>Board width for the preview</source>
        <translation>Širina deske za predogled</translation>
    </message>
    <message>
        <location line="-446"/>
        <source>G-code, DXF…</source>
        <translation>G-koda, DXF…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Head W1</source>
        <translation>Glava W1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rise D</source>
        <translation>Dvig D</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius R</source>
        <translation>Polmer R</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 of %2 recipes</source>
        <translation>%1 od %2 receptov</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>%1 to %2 mm</source>
        <translation>%1 do %2 mm</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>cuts no board here</source>
        <translation>tu ne reže nobene deske</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>on the machine, %1</source>
        <translation>na stroju, %1</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>Unsaved changes</source>
        <translation>Neshranjene spremembe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Discard the changes to %1?</source>
        <translation>Zavržem spremembe recepta %1?</translation>
    </message>
    <message>
        <location line="+97"/>
        <source>The name %1 is already used by recipe %2.</source>
        <translation>Ime %1 že uporablja recept %2.</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Import a side profile (DXF)</source>
        <translation>Uvoz stranskega profila (DXF)</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+11"/>
        <source>Drawing not imported</source>
        <translation>Risba ni uvožena</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>Layer of the side profile</source>
        <translation>Plast s profilom stranice</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>No recipe</source>
        <translation>Ni recepta</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+256"/>
        <source>New recipe</source>
        <translation>Nov recept</translation>
    </message>
    <message>
        <location line="-254"/>
        <source>Recipe %1</source>
        <translation>Recept %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>(changed, not saved)</source>
        <translation>(spremenjen, ni shranjen)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Import a DXF file…</source>
        <translation>Uvozi datoteko DXF…</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>from the barrel, for a %1 mm board</source>
        <translation>iz soda, za desko %1 mm</translation>
    </message>
    <message>
        <location line="+71"/>
        <source>This recipe cuts no board on this machine</source>
        <translation>Ta recept na tem stroju ne reže nobene deske</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Boards it cuts on this machine: %1 to %2 mm</source>
        <translation>Deske, ki jih reže na tem stroju: %1 do %2 mm</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Outside the widths this recipe cuts on this machine</source>
        <translation>Zunaj širin, ki jih ta recept reže na tem stroju</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Not saved</source>
        <translation>Ni shranjeno</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>No user account to save as.</source>
        <translation>Ni uporabniškega računa za shranjevanje.</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+3"/>
        <source>Recipe not saved</source>
        <translation>Recept ni shranjen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Recipe %1 saved.</source>
        <translation>Recept %1 je shranjen.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Use the new version?</source>
        <translation>Uporabim novo različico?</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Recipe %1 is selected on the machine. Cut the saved version from the next board on? Cancel: the machine keeps the version it has.</source>
        <translation>Recept %1 je izbran na stroju. Naj od naslednje deske naprej reže shranjeno različico? Prekliči: stroj obdrži različico, ki jo ima.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Use the new version</source>
        <translation>Uporabi novo različico</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Not changed on the machine</source>
        <translation>Na stroju ni spremenjeno</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+12"/>
        <source>Recipe %1 selected.</source>
        <translation>Recept %1 je izbran.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>New recipe %1</source>
        <translation>Nov recept %1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Name of the copy</source>
        <translation>Ime kopije</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 copy</source>
        <translation>%1 kopija</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Choose a new name.</source>
        <translation>Izberite novo ime.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Not copied</source>
        <translation>Ni kopirano</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Recipe %1 created.</source>
        <translation>Recept %1 je ustvarjen.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Recipe %1 is selected on the machine: select another recipe there first.</source>
        <translation>Recept %1 je izbran na stroju: najprej tam izberite drug recept.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Delete recipe</source>
        <translation>Izbriši recept</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete recipe %1 (%2)? Its last version stays in the recipe history.</source>
        <translation>Izbrišem recept %1 (%2)? Njegova zadnja različica ostane v zgodovini receptov.</translation>
    </message>
    <message>
        <location line="-10"/>
        <location line="+28"/>
        <source>Not deleted</source>
        <translation>Ni izbrisano</translation>
    </message>
    <message>
        <location line="-757"/>
        <source>Barrel type</source>
        <translation>Vrsta soda</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>%1 to below 1</source>
        <translation>od %1 do manj kot 1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the tilt: fixed, or from the barrel</source>
        <translation>nagib: stalen ali iz soda</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Fixed tilt</source>
        <translation>Stalen nagib</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Round</source>
        <translation>Okrogel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Oval</source>
        <translation>Ovalen</translation>
    </message>
    <message>
        <location line="+688"/>
        <source>Recipe %1 deleted.</source>
        <translation>Recept %1 je izbrisan.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Import recipes</source>
        <translation>Uvoz receptov</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Import failed</source>
        <translation>Uvoz ni uspel</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>… and %1 more lines</source>
        <translation>… in še %1 vrstic</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: %2 accepted (%3 new, %4 updated, %5 unchanged), %6 rejected</source>
        <translation>%1: sprejetih %2 (%3 novih, %4 posodobljenih, %5 nespremenjenih), zavrnjenih %6</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>row %1 (%2)</source>
        <translation>vrstica %1 (%2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>row %1</source>
        <translation>vrstica %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Export recipes</source>
        <translation>Izvoz receptov</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+50"/>
        <source>Export failed</source>
        <translation>Izvoz ni uspel</translation>
    </message>
    <message>
        <location line="-47"/>
        <source>%1 recipes written to %2.</source>
        <translation>Število receptov, zapisanih v %2: %1.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Nothing to export</source>
        <translation>Ni česa izvoziti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Select a saved recipe (save the changes first).</source>
        <translation>Izberite shranjen recept (najprej shranite spremembe).</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>LinuxCNC program, %1</source>
        <translation>Program LinuxCNC, %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LinuxCNC, parametric (every width)</source>
        <translation>LinuxCNC, parametrični (vse širine)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SINUMERIK program, %1</source>
        <translation>Program SINUMERIK, %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DXF drawing, %1</source>
        <translation>Risba DXF, %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Program for another control</source>
        <translation>Program za drug krmilnik</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Not exported</source>
        <translation>Ni izvoženo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Write the program</source>
        <translation>Zapiši program</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Written to %1.</source>
        <translation>Zapisano v %1.</translation>
    </message>
</context>
<context>
    <name>Roles</name>
    <message>
        <location filename="../../app/screens/texts.py" line="-7"/>
        <source>Operator</source>
        <translation>Operater</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Technician</source>
        <translation>Tehnik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Service</source>
        <translation>Servis</translation>
    </message>
</context>
<context>
    <name>RuleText</name>
    <message>
        <location line="-49"/>
        <source>This value is not allowed</source>
        <translation>Ta vrednost ni dovoljena</translation>
    </message>
    <message>
        <location filename="catalogue_strings.py" line="+1"/>
        <source>%1 is not a barrel type: allowed fixed tilt, round or oval</source>
        <translation>%1 ni vrsta soda: dovoljeno stalen nagib, okrogel ali ovalen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is not a number</source>
        <translation>%1 ni število</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is not a text</source>
        <translation>%1 ni besedilo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is not allowed: above 0 and below 1</source>
        <translation>%1 ni dovoljeno: več kot 0 in manj kot 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is not allowed: from 0 to below 1/2 (at 1/2 or more no arc is left)</source>
        <translation>%1 ni dovoljeno: od 0 do manj kot 1/2 (pri 1/2 ali več ne ostane noben lok)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is outside the allowed range: %2 to %3 %4</source>
        <translation>%1 je zunaj dovoljenega območja: od %2 do %3 %4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is outside the allowed range: empty, or %2 to %3 %4</source>
        <translation>%1 je zunaj dovoljenega območja: prazno ali od %2 do %3 %4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 leaves nothing to cut (the head as wide as the belly): allowed below 1</source>
        <translation>%1 ne pusti ničesar za rezanje (glava je široka kot trebuh): dovoljeno manj kot 1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 makes the head narrower than %2 mm even on a board of %3 mm: allowed %4 to below 1</source>
        <translation>%1 naredi glavo ožjo od %2 mm celo na deski %3 mm: dovoljeno od %4 do manj kot 1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 mm fits no board of this recipe: boards of %2 to %3 mm need a tilt of %4 to %5°</source>
        <translation>%1 mm ne ustreza nobeni deski tega recepta: deske od %2 do %3 mm potrebujejo nagib od %4 do %5°</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 mm has no use with a fixed tilt: leave the short axis empty, or choose an oval barrel</source>
        <translation>%1 mm nima pomena pri stalnem nagibu: pustite kratko os prazno ali izberite ovalen sod</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 mm has no use with a round barrel: leave the short axis empty, or choose an oval barrel</source>
        <translation>%1 mm nima pomena pri okroglem sodu: pustite kratko os prazno ali izberite ovalen sod</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 mm is not allowed: the short axis is %2 mm up to the long axis, %3 mm</source>
        <translation>%1 mm ni dovoljeno: kratka os meri od %2 mm do dolge osi, %3 mm</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 mm would make the head %2 mm wide: allowed %3 mm or more</source>
        <translation>pri %1 mm bi bila glava široka %2 mm: dovoljeno %3 mm ali več</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1° fits no barrel of %2 to %3 mm for the boards of this recipe: allowed %4 to %5°</source>
        <translation>%1° pri deskah tega recepta ne ustreza nobenemu sodu od %2 do %3 mm: dovoljeno od %4 do %5°</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A board of %1 mm does not fit a barrel of %2 mm</source>
        <translation>Deska %1 mm ne ustreza sodu %2 mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A board of %1 mm is narrower than the stave it should become, %2 mm</source>
        <translation>Deska %1 mm je ožja od doge, ki naj bi iz nje nastala, %2 mm</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A board of %1 mm is outside the widths this machine takes: up to %2 mm</source>
        <translation>Deska %1 mm je zunaj širin, ki jih stroj sprejme: do %2 mm</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A drawn profile needs a drawing: import a DXF file</source>
        <translation>Narisan profil potrebuje risbo: uvozite datoteko DXF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A round or oval barrel needs its belly diameter: allowed %1 to %2 mm</source>
        <translation>Okrogel ali ovalen sod potrebuje premer trebuha: dovoljeno od %1 do %2 mm</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>An oval barrel needs its short axis</source>
        <translation>Ovalen sod potrebuje kratko os</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>At %1° a board of %2 mm belongs to a barrel of %3 mm, outside %4 to %5 mm: allowed %6 to %7°</source>
        <translation>Pri %1° deska %2 mm pripada sodu %3 mm, zunaj območja od %4 do %5 mm: dovoljeno od %6 do %7°</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>At %1° the bevels of a %2 mm thick stave meet before the top face at the %3 mm wide heads: allowed below %4°</source>
        <translation>Pri %1° se poševnini %2 mm debele doge stakneta pred zgornjo ploskvijo na %3 mm širokih glavah: dovoljeno manj kot %4°</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No tilt fits a board of %1 mm: no barrel of %2 to %3 mm has such staves</source>
        <translation>Deski %1 mm ne ustreza noben nagib: noben sod od %2 do %3 mm nima takih dog</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Only a drawn side profile keeps a drawing</source>
        <translation>Risbo ima le narisan stranski profil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The barrel gives a board of %1 mm a tilt of %2°: allowed %3 to %4°</source>
        <translation>Sod da deski %1 mm nagib %2°: dovoljeno od %3 do %4°</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The drawing&apos;s file is not recorded: import the DXF file again</source>
        <translation>Datoteka risbe ni zabeležena: ponovno uvozite datoteko DXF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The head would be %1 mm wide: allowed %2 mm or more</source>
        <translation>Glava bi bila široka %1 mm: dovoljeno %2 mm ali več</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The name contains a control character</source>
        <translation>Ime vsebuje krmilni znak</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The name is empty: allowed 1 to %1 characters</source>
        <translation>Ime je prazno: dovoljeno od 1 do %1 znakov</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The name must have 1 to %1 characters, with no space at its start or end</source>
        <translation>Ime mora imeti od 1 do %1 znakov, brez presledka na začetku ali koncu</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The note has %1 characters: allowed at most %2</source>
        <translation>Opomba ima %1 znakov: dovoljeno največ %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The tool path reaches %1 = %2 %3, beyond the axis travel %4 to %5 %3</source>
        <translation>Pot orodja doseže %1 = %2 %3, zunaj hoda osi od %4 do %5 %3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>This side profile has no parameters</source>
        <translation>Ta stranski profil nima parametrov</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This side profile has no such parameter</source>
        <translation>Ta stranski profil nima takega parametra</translation>
    </message>
</context>
<context>
    <name>SimPendantPanel</name>
    <message>
        <location filename="../../app/screens/widgets/sim_pendant.py" line="+168"/>
        <source>Handwheel and joystick</source>
        <translation>Ročno kolo in igralna palica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Handwheel</source>
        <translation>Ročno kolo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Joystick (hold)</source>
        <translation>Igralna palica (držite)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Off</source>
        <translation>Izklop</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Hold enable</source>
        <translation>Držite omogočanje</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Leave manual mode</source>
        <translation>Zapusti ročni način</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Enter manual mode</source>
        <translation>Vstopi v ročni način</translation>
    </message>
</context>
<context>
    <name>States</name>
    <message>
        <location filename="../../app/screens/texts.py" line="+5"/>
        <source>STARTING UP</source>
        <translation>ZAGANJANJE</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NOT HOMED</source>
        <translation>NI REFERENCIRANO</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HOMING</source>
        <translation>REFERENCIRANJE</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>READY</source>
        <translation>PRIPRAVLJEN</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RUNNING</source>
        <translation>DELUJE</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MANUAL</source>
        <translation>ROČNO</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>STOPPING</source>
        <translation>USTAVLJANJE</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FAULT</source>
        <translation>NAPAKA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>EMERGENCY STOP</source>
        <translation>ZASILNA ZAUSTAVITEV</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>NO MACHINE</source>
        <translation>NI STROJA</translation>
    </message>
</context>
<context>
    <name>StepTimes</name>
    <message>
        <location filename="../../app/screens/widgets/step_times_bar.py" line="+22"/>
        <source>Waiting</source>
        <translation>Čakanje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Centering</source>
        <translation>Centriranje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clamping</source>
        <translation>Vpenjanje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measuring</source>
        <translation>Merjenje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spindle</source>
        <translation>Vreteno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moving clear</source>
        <translation>Umik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Approach</source>
        <translation>Približevanje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side A</source>
        <translation>Stran A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Repositioning</source>
        <translation>Prestavljanje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side B</source>
        <translation>Stran B</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Return</source>
        <translation>Vrnitev</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unclamping</source>
        <translation>Odpenjanje</translation>
    </message>
</context>
<context>
    <name>Steps</name>
    <message>
        <location filename="../../app/screens/texts.py" line="-47"/>
        <source>Waiting for a board</source>
        <translation>Čakam na desko</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Centering</source>
        <translation>Centriranje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clamping</source>
        <translation>Vpenjanje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measuring the width</source>
        <translation>Merjenje širine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moving clear of the board</source>
        <translation>Umik stran od deske</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Starting the spindle</source>
        <translation>Zagon vretena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cutting side A</source>
        <translation>Rezanje stranice A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Repositioning and tilting</source>
        <translation>Premik in nagib</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cutting side B</source>
        <translation>Rezanje stranice B</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Returning</source>
        <translation>Vračanje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unclamping</source>
        <translation>Odpenjanje</translation>
    </message>
</context>
<context>
    <name>SystemScreen</name>
    <message>
        <location filename="../../app/screens/system_screen.py" line="+221"/>
        <source>System</source>
        <translation>Sistem</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Home position</source>
        <translation>Referenčna lega</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tool and machine</source>
        <translation>Orodje, stroj</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start position P0</source>
        <translation>Začetna lega P0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Automatic speeds</source>
        <translation>Avtomatika</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tool path</source>
        <translation>Pot orodja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Axis limits</source>
        <translation>Meje osi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jogging</source>
        <translation>Ročni premiki</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shifts</source>
        <translation>Izmene</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change log</source>
        <translation>Dnevnik sprememb</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OPC UA</source>
        <translation>OPC UA</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+27"/>
        <source>Simulation</source>
        <translation>Simulacija</translation>
    </message>
    <message>
        <location line="-20"/>
        <source>The system settings are locked.
Log in as technician or service to change them.</source>
        <translation>Sistemske nastavitve so zaklenjene.
Za spremembe se prijavite kot tehnik ali servis.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Unlock with PIN</source>
        <translation>Odkleni s PIN-om</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lock (log out)</source>
        <translation>Zakleni (odjava)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Change log of the system parameters</source>
        <translation>Dnevnik sprememb sistemskih parametrov</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Time</source>
        <translation>Čas</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Old</source>
        <translation>Staro</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>New</source>
        <translation>Novo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>User</source>
        <translation>Uporabnik</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Only on the simulated machine: inject a fault to test the alarms, clear the injected faults (the machine stays latched until Reset), put a board in, take it off or replace it, and work the handwheel and the joystick (in manual mode).</source>
        <translation>Samo na simuliranem stroju: vstavite napako za preizkus alarmov, počistite vstavljene napake (stroj ostane zaklenjen do ponastavitve), vstavite desko, jo odstranite ali zamenjajte ter upravljajte ročno kolo in igralno palico (v ročnem načinu).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Clear injected faults</source>
        <translation>Odstrani vstavljene napake</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Put a board in</source>
        <translation>Vstavi desko</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Take the board off</source>
        <translation>Odstrani desko</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replace the board</source>
        <translation>Zamenjaj desko</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>needs %1</source>
        <translation>potrebna raven: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>enforced by the machine, set in its configuration file</source>
        <translation>stroj jih upošteva, nastavljene so v njegovi konfiguracijski datoteki</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Log in to change parameters.</source>
        <translation>Za spremembo parametrov se prijavite.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 set to %2 (logged).</source>
        <translation>%1 nastavljen na %2 (zabeleženo).</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Fault injected: %1</source>
        <translation>Vstavljena napaka: %1</translation>
    </message>
</context>
<context>
    <name>TextKeyboard</name>
    <message>
        <location filename="../../app/screens/widgets/keyboard.py" line="+122"/>
        <source>Space</source>
        <translation>Presledek</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Prekliči</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OK</source>
        <translation>V redu</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>At most %1 characters.</source>
        <translation>Največ %1 znakov.</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Enter a text.</source>
        <translation>Vnesite besedilo.</translation>
    </message>
</context>
</TS>
