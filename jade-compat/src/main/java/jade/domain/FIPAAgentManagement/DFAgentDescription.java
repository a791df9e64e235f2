package jade.domain.FIPAAgentManagement;

import jade.core.AID;
import jade.util.leap.ArrayList;
import jade.util.leap.Iterator;

import java.util.Date;

/** An agent's entry in the yellow pages: its AID and the services it offers. */
public class DFAgentDescription implements jade.content.Concept {
    private static final long serialVersionUID = 1L;
    private AID name;
    private Date leaseTime;
    private final ArrayList services = new ArrayList();
    private final ArrayList protocols = new ArrayList();
    private final ArrayList ontologies = new ArrayList();
    private final ArrayList languages = new ArrayList();

    public DFAgentDescription() {
    }

    public void setName(AID n) {
        name = n;
    }

    public AID getName() {
        return name;
    }

    public void setLeaseTime(Date d) {
        leaseTime = d;
    }

    public Date getLeaseTime() {
        return leaseTime;
    }

    public void setRelativeLeaseTime(long ms) {
        leaseTime = new Date(io.concord.jadecompat.internal.Engine.nowMs() + ms);
    }

    /** True if a lease time was given and has passed. */
    public boolean checkLeaseTimeExpired() {
        return leaseTime != null && leaseTime.getTime() < io.concord.jadecompat.internal.Engine.nowMs();
    }

    public void addServices(ServiceDescription s) {
        services.add(s);
    }

    public boolean removeServices(ServiceDescription s) {
        return services.remove(s);
    }

    public void clearAllServices() {
        services.clear();
    }

    public Iterator getAllServices() {
        return services.iterator();
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
}
