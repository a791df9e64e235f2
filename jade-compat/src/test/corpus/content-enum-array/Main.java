import jade.content.ContentManager;
import jade.content.lang.sl.SLCodec;
import jade.content.onto.BasicOntology;
import jade.content.onto.BeanOntology;
import jade.content.onto.basic.Action;
import jade.core.AID;
import jade.lang.acl.ACLMessage;

import java.util.Arrays;

/**
 * A BeanOntology with an enum slot and array slots, and a hand-written ontology whose slot names
 * are in capitals: the SL text each writes, and what comes back, without a platform.
 */
public class Main {
    public static void main(String[] args) throws Exception {
        BeanOntology parcels = new BeanOntology("parcels", BasicOntology.getInstance());
        parcels.add(Parcel.class);
        ContentManager cm = new ContentManager();
        cm.registerLanguage(new SLCodec());
        cm.registerOntology(parcels);
        cm.registerOntology(new FamilyOntology());

        Parcel inner = new Parcel();
        inner.setLabel("inner");
        inner.setSize(Size.SMALL);
        Parcel p = new Parcel();
        p.setLabel("box");
        p.setSize(Size.LARGE);
        p.setWeights(new double[] {1.5, 2.25});
        p.setStickers(new String[] {"fragile", "this side up"});
        p.setInside(new Parcel[] {inner});
        Action a = new Action(new AID("post@P", AID.ISGUID), p);
        ACLMessage m = new ACLMessage(ACLMessage.INFORM);
        m.setLanguage(new SLCodec().getName());
        m.setOntology(parcels.getName());
        try {
            cm.fillContent(m, a);
            System.out.println("parcel: " + m.getContent());
            Parcel back = (Parcel) ((Action) cm.extractContent(m)).getAction();
            System.out.println("back: " + back.getLabel() + " " + back.getSize() + " " + Arrays.toString(back.getWeights()) + " "
                    + Arrays.toString(back.getStickers()) + " inside " + back.getInside().length + " " + back.getInside()[0].getLabel()
                    + " " + back.getInside()[0].getSize() + " weights " + Arrays.toString(back.getInside()[0].getWeights()));
        } catch (Exception e) {
            System.out.println("parcel failed: " + e);
        }

        Person grandpa = new Person();
        grandpa.setName("Abe");
        Person dad = new Person();
        dad.setName("Homer");
        dad.setAge(39);
        dad.setFather(grandpa);
        ACLMessage f = new ACLMessage(ACLMessage.INFORM);
        f.setLanguage(new SLCodec().getName());
        f.setOntology(FamilyOntology.NAME);
        try {
            cm.fillContent(f, new Action(new AID("census@P", AID.ISGUID), dad));
            System.out.println("person: " + f.getContent());
            Person back = (Person) ((Action) cm.extractContent(f)).getAction();
            System.out.println("back: " + back.getName() + " " + back.getAge() + " father " + back.getFather().getName() + " "
                    + back.getFather().getFather());
        } catch (Exception e) {
            System.out.println("person failed: " + e);
        }
    }
}
