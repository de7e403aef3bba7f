<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.10" tiledversion="1.10.2" name="level-tiles" tilewidth="16" tileheight="16" tilecount="5" columns="5">
 <image source="level-tiles.png" width="80" height="16"/>
 <tile id="0" type="one-way">
  <properties>
   <property name="one-way" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="1" type="breakable">
  <properties>
   <property name="solid" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="2" type="ramp">
  <objectgroup draworder="index" id="2">
   <object id="1" x="0" y="0">
    <polygon points="0,16 16,16 16,0"/>
   </object>
  </objectgroup>
 </tile>
 <tile id="3" type="ramp">
  <objectgroup draworder="index" id="2">
   <object id="1" x="0" y="0">
    <polygon points="0,16 16,16 16,8"/>
   </object>
  </objectgroup>
 </tile>
 <tile id="4" type="ramp">
  <objectgroup draworder="index" id="2">
   <object id="1" x="0" y="0">
    <polygon points="0,16 16,16 16,0 0,8"/>
   </object>
  </objectgroup>
 </tile>
</tileset>
