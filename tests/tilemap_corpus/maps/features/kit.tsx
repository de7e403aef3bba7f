<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.8" tiledversion="1.8.2" name="kit" tilewidth="16" tileheight="16" tilecount="8" columns="4">
 <tileoffset x="2" y="-4"/>
 <properties>
  <property name="author" value="corpus"/>
 </properties>
 <image source="kit.png" width="64" height="32"/>
 <tile id="0" type="ground">
  <properties>
   <property name="solid" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="1" type="ledge">
  <properties>
   <property name="one-way" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="2" type="slope">
  <objectgroup draworder="index">
   <object id="1" x="0" y="0">
    <polygon points="0,16 16,0 16,16"/>
   </object>
  </objectgroup>
 </tile>
 <tile id="3" type="torch">
  <animation>
   <frame tileid="3" duration="120"/>
   <frame tileid="7" duration="80"/>
  </animation>
 </tile>
 <tile id="4">
  <properties>
   <property name="one-way" type="bool" value="true"/>
   <property name="solid" type="bool" value="true"/>
  </properties>
 </tile>
 <tile id="5">
  <properties>
   <property name="collides" type="bool" value="false"/>
   <property name="one-way" type="bool" value="false"/>
  </properties>
 </tile>
</tileset>
