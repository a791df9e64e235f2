package jade.domain.FIPAAgentManagement;

import jade.util.leap.ArrayList;
import jade.util.leap.Iterator;

/** A service an agent offers: type, name, properties, protocols, ontologies, languages, ownership. */
public class ServiceDescription implements jade.content.Concept {
    private static final long serialVersionUID = 1L;
    private String name;
    private String type;
    private String ownership;
    private final ArrayList protocols = new ArrayList();
    private final ArrayList ontologies = new ArrayList();
    private final ArrayList languages = new ArrayList();
    private final ArrayList properties = new ArrayList();

    public ServiceDescription() {
    }

    public void setName(String n) {
        name = n;
    }

    public String getName() {
        return name;
    }

    public void setType(String t) {
        type = t;
    }

    public String getType() {
        return type;
    }

    public void setOwnership(String o) {
        ownership = o;
    }

    public String getOwnership() {
        return ownership;
    }

    public void addProtocols(String p) {
        protocols.add(p);
    }

    public boolean removeProtocols(String p) {
        return protocols.remove(p);
    }

    public void clearAllProtocols() {
        protocols.clear();
    }

    public Iterator getAllProtocols() {
        return protocols.iterator();
    }

    public void addOntologies(String o) {
        ontologies.add(o);
    }

    public boolean removeOntologies(String o) {
        return ontologies.remove(o);
    }

    public void clearAllOntologies() {
        ontologies.clear();
    }

    public Iterator getAllOntologies() {
        return ontologies.iterator();
    }

    public void addLanguages(String l) {
        languages.add(l);
    }

    public boolean removeLanguages(String l) {
        return languages.remove(l);
    }

    public void clearAllLanguages() {
        languages.clear();
    }

    public Iterator getAllLanguages() {
        return languages.iterator();
    }

    public void addProperties(Property p) {
        properties.add(p);
    }

    public boolean removeProperties(Property p) {
        return properties.remove(p);
    }

    public void clearAllProperties() {
        properties.clear();
    }

    public Iterator getAllProperties() {
        return properties.iterator();
    }
}
